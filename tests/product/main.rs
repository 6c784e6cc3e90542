//! Tests of the whole product: the command line, scene files, exports, reference images.

mod answers;
mod app;
mod architecture;
mod authoring;
mod check;
mod cli;
mod corpus;
mod course;
mod edit;
mod grade;
mod handout;
mod lab_corpus;
mod lab_corpus_geometry;
mod lab_corpus_shading;
mod lab_hooks;
mod lab_solutions;
mod labs;
mod lesson_mistakes;
mod lessons;
mod observer;
mod record;
mod reference;
mod scene_file;
mod shader_handout;
mod shader_lesson;
mod support;
