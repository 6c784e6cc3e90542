//! Arbitrary GLSL through the student's path: adapted to naga's dialect, parsed, validated,
//! checked against pipelens' interface, linked, then run on a small frame. Never a panic and
//! never a hang (the run's step budget stops endless loops): a shader that does not compile is
//! messages whose lines are inside its source, one that fails while running is a render error.
#![no_main]

use std::sync::Arc;

use libfuzzer_sys::fuzz_target;
use pipeline::mesh::BuiltinMesh;
use pipeline::scene::{Object, ObjectShader, Scene};
use pipeline::settings::RenderSettings;

fuzz_target!(|data: &[u8]| {
    let Some((&pick, rest)) = data.split_first() else {
        return;
    };
    let Ok(source) = std::str::from_utf8(rest) else {
        return;
    };
    // The first byte says which stage the text is.
    let vertex_stage = pick & 1 == 1;
    let linked = if vertex_stage {
        pipeline::shader::link(Some(source), None)
    } else {
        pipeline::shader::link(None, Some(source))
    };
    let programs = match linked {
        Ok(p) => p,
        Err(errors) => {
            assert!(!errors.is_empty(), "a failed link says why");
            for e in &errors {
                // A link error may point into pipelens' own shader of the other stage.
                let text = match (e.stage, vertex_stage) {
                    (pipeline::shader::Stage::Vertex, false) => pipeline::shader::BUILTIN_VERTEX,
                    (pipeline::shader::Stage::Fragment, true) => pipeline::shader::BUILTIN_FRAGMENT,
                    _ => source,
                };
                let lines = text.lines().count().max(1);
                assert!(
                    e.error.line >= 1 && e.error.line <= lines + 1,
                    "line {} outside a {lines}-line source: {}",
                    e.error.line,
                    e.error.message
                );
                assert!(e.error.column >= 1, "{}", e.error.message);
            }
            return;
        }
    };
    let mut object = Object::new("fuzz", BuiltinMesh::UvSphere { segments: 8, rings: 5 }.build());
    object.shader = Some(ObjectShader {
        programs: Arc::new(programs),
        time: f32::from(pick >> 1),
    });
    let scene = Scene {
        objects: vec![object],
        ..Scene::default()
    };
    let settings = RenderSettings {
        width: 24,
        height: 16,
        ..RenderSettings::default()
    };
    // Ok or a message; a NaN colour is drawn black and counted, never passed on.
    if let Ok(capture) = pipeline::render(&scene, &settings) {
        assert!(capture.pixels.color.iter().flatten().all(|v| v.is_finite()));
    }
});
