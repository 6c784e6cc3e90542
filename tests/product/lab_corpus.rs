//! The labs' corpus: for every lab, wrong solutions of the kinds students hand in, each graded
//! failed with the check's sentence, and correct ones written differently (helper functions,
//! another algebraic form, `mix`, a positive multiple where that is right), each graded passed —
//! through `pipelens::lab::submission::grade`, the check the app and `pipelens grade` make.
//! Shortcuts (pipelens' own matrix or filter taken where the lab asks for it) are refused.

use pipelens::lab::submission::{Code, grade};
use pipelens::lesson::Document;
use pipelens::vocabulary::Lang;

use crate::labs::SOLUTIONS;

/// What a hand-in should be graded.
enum Want {
    /// Passed.
    Right,
    /// Failed, its sentences holding each of these words.
    Wrong(&'static [&'static str]),
}

use Want::{Right, Wrong};

/// `(lesson, the lab's title, the code in place of the starter's TODO, what it should get)`.
const CORPUS: &[(&str, &str, &str, Want)] = &[
    // 02: Rodrigues' formula.
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = axis;
    float t = radians(deg);
    mat3 cross_n = mat3(0.0, n.z, -n.y, -n.z, 0.0, n.x, n.y, -n.x, 0.0);
    return cos(t) * mat3(1.0) + (1.0 - cos(t)) * outerProduct(n, n) + sin(t) * cross_n;", Wrong(&["Not yet", "The first vertex off"])),
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = normalize(axis);
    float t = deg;
    mat3 cross_n = mat3(0.0, n.z, -n.y, -n.z, 0.0, n.x, n.y, -n.x, 0.0);
    return cos(t) * mat3(1.0) + (1.0 - cos(t)) * outerProduct(n, n) + sin(t) * cross_n;", Wrong(&["Not yet", "The first vertex off"])),
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = normalize(axis);
    float t = radians(deg);
    mat3 cross_n = mat3(0.0, -n.z, n.y, n.z, 0.0, -n.x, -n.y, n.x, 0.0);
    return cos(t) * mat3(1.0) + (1.0 - cos(t)) * outerProduct(n, n) + sin(t) * cross_n;", Wrong(&["Not yet", "The first vertex off"])),
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = normalize(axis);
    float t = radians(deg);
    mat3 cross_n = mat3(0.0, n.z, -n.y, -n.z, 0.0, n.x, n.y, -n.x, 0.0);
    return cos(t) * mat3(1.0) + outerProduct(n, n) + sin(t) * cross_n;", Wrong(&["Not yet", "The first vertex off"])),
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = normalize(axis);
    float t = radians(deg);
    return cos(t) * mat3(1.0) + (1.0 - cos(t)) * outerProduct(n, n);", Wrong(&["Not yet", "The first vertex off"])),
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = axis / length(axis);
    float c = cos(deg * 3.14159265 / 180.0);
    float s = sin(deg * 3.14159265 / 180.0);
    mat3 r;
    for (int j = 0; j < 3; j++) {
        vec3 e = vec3(0.0);
        e[j] = 1.0;
        r[j] = c * e + (1.0 - c) * dot(n, e) * n + s * cross(n, e);
    }
    return r;", Right),
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = normalize(axis);
    float t = radians(deg);
    mat3 k = mat3(vec3(0.0, n.z, -n.y), vec3(-n.z, 0.0, n.x), vec3(n.y, -n.x, 0.0));
    return mat3(1.0) + sin(t) * k + (1.0 - cos(t)) * (k * k);", Right),
    // 03: LookAt.
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(at - eye);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                -dot(u, eye), -dot(v, eye), -dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, u.y, u.z, 0.0, v.x, v.y, v.z, 0.0, n.x, n.y, n.z, 0.0,
                -dot(u, eye), -dot(v, eye), -dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                dot(u, eye), dot(v, eye), dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(n, up));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                -dot(u, eye), -dot(v, eye), -dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                -eye.x, -eye.y, -eye.z, 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "uniform mat4 view;
---
    return view;", Wrong(&["declares pipelens' own `view`"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    mat4 r = transpose(mat4(vec4(u, 0.0), vec4(v, 0.0), vec4(n, 0.0), vec4(0.0, 0.0, 0.0, 1.0)));
    mat4 t = mat4(1.0);
    t[3] = vec4(-eye, 1.0);
    return r * t;", Right),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 f = normalize(at - eye);
    vec3 s = normalize(cross(f, up));
    vec3 w = cross(s, f);
    mat4 view = mat4(1.0);   // a local: not pipelens' uniform
    view[0] = vec4(s.x, w.x, -f.x, 0.0);
    view[1] = vec4(s.y, w.y, -f.y, 0.0);
    view[2] = vec4(s.z, w.z, -f.z, 0.0);
    view[3] = vec4(-dot(s, eye), -dot(w, eye), dot(f, eye), 1.0);
    return view;", Right),
    // 06: the viewport matrix.
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w, 0.0, 0.0, 0.0, 0.0, h, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0,
                w / 2.0, h / 2.0, 0.5, 1.0);", Wrong(&["Not yet"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, 0.0, 0.0, h / 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
                w / 2.0, h / 2.0, 0.0, 1.0);", Wrong(&["Not yet"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, w / 2.0, 0.0, h / 2.0, 0.0, h / 2.0, 0.0, 0.0, 0.5, 0.5,
                0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, 0.0, 0.0, -h / 2.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0,
                w / 2.0, h / 2.0, 0.5, 1.0);", Wrong(&["Not yet"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, 0.0, 0.0, h / 2.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0,
                w / 2.0 - 0.5, h / 2.0 - 0.5, 0.5, 1.0);", Wrong(&["Not yet"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    mat4 s = mat4(vec4(w / 2.0, 0.0, 0.0, 0.0), vec4(0.0, h / 2.0, 0.0, 0.0),
                  vec4(0.0, 0.0, 0.5, 0.0), vec4(0.0, 0.0, 0.0, 1.0));
    mat4 t = mat4(1.0);
    t[3] = vec4(1.0, 1.0, 1.0, 1.0);
    return s * t;", Right),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    mat4 m = mat4(0.0);
    m[0][0] = 0.5 * w;
    m[1][1] = 0.5 * h;
    m[2][2] = 0.5;
    m[3] = vec4(0.5 * w, 0.5 * h, 0.5, 1.0);
    return m;", Right),
    // 09: the depth test.
    ("09-z-buffer", "Lab: the depth test", "    return z > stored;", Wrong(&["Not yet", "your depth_test(z, stored)"])),
    ("09-z-buffer", "Lab: the depth test", "    return z <= stored;", Wrong(&["Not yet", "your depth_test(z, stored)"])),
    ("09-z-buffer", "Lab: the depth test", "    return stored < z;", Wrong(&["Not yet", "your depth_test(z, stored)"])),
    ("09-z-buffer", "Lab: the depth test", "    return z != stored;", Wrong(&["Not yet", "your depth_test(z, stored)"])),
    ("09-z-buffer", "Lab: the depth test", "    return z < 1.0;", Wrong(&["Not yet", "your depth_test(z, stored)"])),
    ("09-z-buffer", "Lab: the depth test", "    return stored > z;", Right),
    ("09-z-buffer", "Lab: the depth test", "    if (z < stored) {
        return true;
    }
    return false;", Right),
    ("09-z-buffer", "Lab: the depth test", "    return stored - z > 0.0;", Right),
    // 10: the specular term.
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = normalize(l + v);
        sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);", Wrong(&["Not yet"])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 r = reflect(-l, n);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(r, v), 0.0), shininess);
        }", Wrong(&["Not yet"])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = normalize(l + v);
        if (n_dot_l > 0.0) {
            sum += ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }", Wrong(&["Not yet"])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = l + v;
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }", Wrong(&["Not yet"])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = normalize(l + v);
        if (n_dot_l > 0.0) {
            sum += f * ks * c * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }", Wrong(&["Not yet"])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 half_vector = (l + v) / length(l + v);
        float lit = n_dot_l > 0.0 ? 1.0 : 0.0;
        sum += lit * f * light.intensity * ks * pow(max(dot(half_vector, n), 0.0), shininess);", Right),
    // 11: the normal matrix.
    ("11-shading-frequencies", "Lab: the normal matrix", "    return inverse(mat3(m));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return transpose(mat3(m));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return mat3(transpose(m));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return -transpose(inverse(mat3(m)));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "uniform mat3 normal_matrix;
---
    return normal_matrix;", Wrong(&["declares pipelens' own `normal_matrix`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return mat3(transpose(inverse(m)));", Right),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return 2.0 * inverse(transpose(mat3(m)));", Right),
    // 12: the 1/w weights.
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv * clip.w;
    one_over_w = clip.w;", Wrong(&["Not yet"])),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv / clip.w;
    one_over_w = 1.0;", Wrong(&["Not yet"])),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv / clip.z;
    one_over_w = 1.0 / clip.z;", Wrong(&["Not yet"])),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv;
    one_over_w = 1.0 / clip.w;", Wrong(&["Not yet"])),
    ("12-interpolation", "Lab: the 1/w weights", "    float inv = 1.0 / clip.w;
    uv_over_w = uv * inv;
    one_over_w = inv;", Right),
    // 13: bilinear filtering.
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size);
    vec2 f = floor(xy);
    vec2 st = xy - f;
    ivec2 ij = ivec2(f);
    vec3 bottom = mix(texel(ij), texel(ij + ivec2(1, 0)), st.x);
    vec3 top = mix(texel(ij + ivec2(0, 1)), texel(ij + ivec2(1, 1)), st.x);
    return mix(bottom, top, st.y);", Wrong(&["Not yet"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    vec2 st = xy - f;
    ivec2 ij = ivec2(f);
    vec3 bottom = mix(texel(ij), texel(ij + ivec2(1, 0)), st.y);
    vec3 top = mix(texel(ij + ivec2(0, 1)), texel(ij + ivec2(1, 1)), st.x);
    return mix(bottom, top, st.x);", Wrong(&["Not yet"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    ivec2 ij = ivec2(xy);
    vec2 st = xy - vec2(ij);
    vec3 bottom = mix(texel(ij), texel(ij + ivec2(1, 0)), st.x);
    vec3 top = mix(texel(ij + ivec2(0, 1)), texel(ij + ivec2(1, 1)), st.x);
    return mix(bottom, top, st.y);", Wrong(&["Not yet"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    ivec2 ij = ivec2(f);
    return (texel(ij) + texel(ij + ivec2(1, 0)) + texel(ij + ivec2(0, 1)) + texel(ij + ivec2(1, 1))) / 4.0;", Wrong(&["Not yet"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    return texture(tex, uv).rgb;", Wrong(&["calls `texture()`"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    float s = xy.x - f.x;
    float t = xy.y - f.y;
    ivec2 ij = ivec2(f);
    return (1.0 - s) * (1.0 - t) * texel(ij) + s * (1.0 - t) * texel(ij + ivec2(1, 0))
         + (1.0 - s) * t * texel(ij + ivec2(0, 1)) + s * t * texel(ij + ivec2(1, 1));", Right),
    // 14: the level of detail.
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv));
    float ly = length(dFdy(uv));
    return log2(max(max(lx, ly), 1e-12));", Wrong(&["Not yet"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv) * size);
    float ly = length(dFdy(uv) * size);
    return log2(min(lx, ly));", Wrong(&["Not yet"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv) * size);
    float ly = length(dFdy(uv) * size);
    return max(lx, ly);", Wrong(&["Not yet"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv) * size);
    float ly = length(dFdy(uv) * size);
    return log2(max(lx, ly)) + 1.0;", Wrong(&["Not yet"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    vec2 dx = dFdx(uv) * size;
    vec2 dy = dFdy(uv) * size;
    return 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-24));", Right),
    // 16: the shadow matrix.
    ("16-planar-shadows", "Lab: the shadow matrix", "    to_light[3] = vec4(light, 1.0);
    project[1][3] = -1.0 / light.y;
    project[3][3] = 0.0;
    back[3] = vec4(-light, 1.0);", Wrong(&["Not yet", "M_shadow"])),
    ("16-planar-shadows", "Lab: the shadow matrix", "    to_light[3] = vec4(-light, 1.0);
    project[3][1] = -1.0 / light.y;
    project[3][3] = 0.0;
    back[3] = vec4(light, 1.0);", Wrong(&["Not yet", "M_shadow"])),
    ("16-planar-shadows", "Lab: the shadow matrix", "    to_light[3] = vec4(-light, 1.0);
    project[1][3] = -1.0 / light.y;
    back[3] = vec4(light, 1.0);", Wrong(&["Not yet", "M_shadow"])),
    ("16-planar-shadows", "Lab: the shadow matrix", "    to_light[3] = vec4(-light, 1.0);
    project[1][3] = 1.0 / light.y;
    project[3][3] = 0.0;
    back[3] = vec4(light, 1.0);", Wrong(&["Not yet", "M_shadow"])),
    ("16-planar-shadows", "Lab: the shadow matrix", "    return mat4(light.y, 0.0, 0.0, 0.0, -light.x, 0.0, -light.z, -1.0,
                0.0, 0.0, light.y, 0.0, 0.0, 0.0, 0.0, light.y);", Right),
    // 18: de Casteljau.
    ("18-bezier", "Lab: de Casteljau", "    vec2 a = lerp(p0, p1, t);
    vec2 b = lerp(p1, p2, t);
    vec2 c = lerp(p2, p3, t);
    return lerp(a, c, t);", Wrong(&["Not yet"])),
    ("18-bezier", "Lab: de Casteljau", "    vec2 a = lerp(p0, p1, t);
    vec2 b = lerp(p1, p2, t);
    vec2 c = lerp(p2, p3, t);
    vec2 d = lerp(a, b, t);
    vec2 e = lerp(b, c, t);
    return lerp(d, e, 1.0 - t);", Wrong(&["Not yet"])),
    ("18-bezier", "Lab: de Casteljau", "    return lerp(p0, p3, t);", Wrong(&["Not yet"])),
    ("18-bezier", "Lab: de Casteljau", "    float s = 1.0 - t;
    return s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;", Right),
    ("18-bezier", "Lab: de Casteljau", "    vec2 p[4] = vec2[4](p0, p1, p2, p3);
    for (int level = 3; level > 0; level--) {
        for (int i = 0; i < level; i++) {
            p[i] = mix(p[i], p[i + 1], t);
        }
    }
    return p[0];", Right),
    // 25: the rotation about z and the perspective projection.
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    return mat4(cos(t), -sin(t), 0.0, 0.0, sin(t), cos(t), 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = deg;
    return mat4(cos(t), sin(t), 0.0, 0.0, -sin(t), cos(t), 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    return mat4(1.0, 0.0, 0.0, 0.0, 0.0, cos(t), sin(t), 0.0, 0.0, -sin(t), cos(t), 0.0, 0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "The first vertex off"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    return mat4(vec4(cos(t), sin(t), 0.0, 0.0), vec4(-sin(t), cos(t), 0.0, 0.0), vec4(0.0, 0.0, 1.0, 0.0), vec4(0.0, 0.0, 0.0, 1.0));", Right),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), 1.0,
                0.0, 0.0, 2.0 * zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy));
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), -1.0,
                0.0, 0.0, 2.0 * zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f, 0.0, 0.0, 0.0, 0.0, f / aspect, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), -1.0,
                0.0, 0.0, 2.0 * zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "uniform mat4 projection;
---
    return projection;", Wrong(&["declares pipelens' own `projection`"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), -1.0,
                0.0, 0.0, zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet", "lie at another depth"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, zFar / (zNear - zFar), -1.0,
                0.0, 0.0, zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet", "lie at another depth"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float t = radians(fovy) * 0.5;
    float f = cos(t) / sin(t);
    float nf = zNear - zFar;
    return mat4(vec4(f / aspect, 0, 0, 0), vec4(0, f, 0, 0), vec4(0, 0, (zNear + zFar) / nf, -1), vec4(0, 0, 2.0 * zNear * zFar / nf, 0));", Right),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float top = zNear * tan(radians(fovy / 2.0));
    float right = top * aspect;
    return mat4(zNear / right, 0, 0, 0,  0, zNear / top, 0, 0,  0, 0, -(zFar + zNear) / (zFar - zNear), -1,  0, 0, -2.0 * zFar * zNear / (zFar - zNear), 0);", Right),
    // 07: the inside test (the square's corners and diagonal on pixel centres).
    ("07-rasterization", "Lab: the inside test", "    return edge(a, b, p) >= 0.0 && edge(b, c, p) >= 0.0;", Wrong(&["Not yet", "belong to another triangle", "your inside(): inside"])),
    ("07-rasterization", "Lab: the inside test", "    return edge(a, b, p) >= 0.0 && edge(b, c, p) >= 0.0 && edge(c, a, p) >= 0.0;", Wrong(&["Not yet", "your inside()"])),
    ("07-rasterization", "Lab: the inside test", "    return edge(a, b, p) > 0.0 && edge(b, c, p) > 0.0 && edge(c, a, p) > 0.0;", Wrong(&["Not yet", "your inside()"])),
    ("07-rasterization", "Lab: the inside test", "    vec2 corner[3] = vec2[3](a, b, c);
    for (int i = 0; i < 3; i++) {
        vec2 from = corner[i];
        vec2 to = corner[(i + 1) % 3];
        float e = edge(from, to, p);
        bool bottom_right = (to.y == from.y && to.x > from.x) || to.y > from.y;
        if (e < 0.0 || (e == 0.0 && !bottom_right)) {
            return false;
        }
    }
    return true;", Wrong(&["Not yet", "your inside()"])),
    ("07-rasterization", "Lab: the inside test", "    return edge(a, b, p) <= 0.0 && edge(b, c, p) <= 0.0 && edge(c, a, p) <= 0.0;", Wrong(&["Not yet", "your inside()"])),
    ("07-rasterization", "Lab: the inside test", "    return owns(a, b, p) && owns(b, c, p) && owns(c, a, p);
}
bool top_or_left(vec2 from, vec2 to) {
    return (from.y == to.y && to.x < from.x) || to.y < from.y;
}
bool owns(vec2 from, vec2 to, vec2 p) {
    float e = edge(from, to, p);
    return e > 0.0 || (e == 0.0 && top_or_left(from, to));", Wrong(&["Does not compile", "owns"])),
    ("07-rasterization", "Lab: the inside test", "float edge_of(vec2 a, vec2 b, vec2 p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}
bool top_or_left(vec2 from, vec2 to) {
    return (from.y == to.y && to.x < from.x) || to.y < from.y;
}
bool owns(vec2 from, vec2 to, vec2 p) {
    float e = edge_of(from, to, p);
    return e > 0.0 || (e == 0.0 && top_or_left(from, to));
}
---
    return owns(a, b, p) && owns(b, c, p) && owns(c, a, p);", Right),
    ("07-rasterization", "Lab: the inside test", "    float e0 = edge(a, b, p);
    float e1 = edge(b, c, p);
    float e2 = edge(c, a, p);
    bool t0 = (a.y == b.y && b.x < a.x) || b.y < a.y;
    bool t1 = (b.y == c.y && c.x < b.x) || c.y < b.y;
    bool t2 = (c.y == a.y && a.x < c.x) || a.y < c.y;
    return (e0 > 0.0 || (e0 == 0.0 && t0)) && (e1 > 0.0 || (e1 == 0.0 && t1)) && (e2 > 0.0 || (e2 == 0.0 && t2));", Right),
    // 08: the inside test at every sample.
    ("08-antialiasing", "Lab: the inside test at every sample", "    vec2 q = floor(p) + 0.5;
    return edge(a, b, q) >= 0.0 && edge(b, c, q) >= 0.0;", Wrong(&["Not yet", "your inside()"])),
    ("08-antialiasing", "Lab: the inside test at every sample", "    return edge(a, b, p) >= 0.0 && edge(b, c, p) >= 0.0;", Wrong(&["Not yet", "your inside()"])),
    ("08-antialiasing", "Lab: the inside test at every sample", "    vec2 q = p + 0.5;
    return edge(a, b, q) >= 0.0 && edge(b, c, q) >= 0.0 && edge(c, a, q) >= 0.0;", Wrong(&["Not yet", "your inside()"])),
    ("08-antialiasing", "Lab: the inside test at every sample", "    float e0 = edge(a, b, p);
    float e1 = edge(b, c, p);
    float e2 = edge(c, a, p);
    bool t0 = (a.y == b.y && b.x < a.x) || b.y < a.y;
    bool t1 = (b.y == c.y && c.x < b.x) || c.y < b.y;
    bool t2 = (c.y == a.y && a.x < c.x) || a.y < c.y;
    return (e0 > 0.0 || (e0 == 0.0 && t0)) && (e1 > 0.0 || (e1 == 0.0 && t1)) && (e2 > 0.0 || (e2 == 0.0 && t2));", Right),
    // 15: the bump map (a 512×256 relief whose channels differ).
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0 / size.y, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0 / size.x)) - here);
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = height(uv + vec2(1.0 / size.x, 0.0)) - here;
        float dv = height(uv + vec2(0.0, 1.0 / size.y)) - here;
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0 / size.x, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0 / size.y)) - here);
        local = vec3(du, dv, 1.0);", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = textureLod(detail, uv, 0.0).r;
        float du = bump_strength * (textureLod(detail, uv + vec2(1.0 / size.x, 0.0), 0.0).r - here);
        float dv = bump_strength * (textureLod(detail, uv + vec2(0.0, 1.0 / size.y), 0.0).r - here);
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0)) - here);
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 texel_step = 1.0 / vec2(textureSize(detail, 0));
        float h0 = height(uv);
        vec2 d = bump_strength * (vec2(height(uv + vec2(texel_step.x, 0.0)), height(uv + vec2(0.0, texel_step.y))) - h0);
        local = vec3(-d, 1.0);", Right),
    // 15: displacement.
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position + normal * (displacement_scale * textureLod(displacement, uv, 0.0).r);", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position + normal * height(uv);", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position - normal * (displacement_scale * height(uv));", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position + normal * (displacement_scale * height(uv.yx));", Wrong(&["Not yet"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    float k = displacement_scale;
    vec3 p = position;
    p += k * height(uv) * normal;", Right),
    // 24: the diffuse term.
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * light_color * max(dot(n, l), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * v_color * light_color * dot(n, l);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * v_color * light_color * max(dot(n, v), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L = kd * v_color * light_color * max(dot(n, l), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * v_color * max(dot(n, h), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    float lambert = clamp(dot(l, n), 0.0, 1.0);
    L = L + lambert * light_color * v_color * kd;", Right),
    ("24-shader-programs", "Lab: the diffuse term", "    L += mix(vec3(0.0), kd * v_color * light_color, max(dot(n, l), 0.0));", Right),
];

/// The lab titled `title` in `lesson`: its step and the lesson.
fn lab(lesson_id: &str, title: &str) -> (pipelens::lesson::Lesson, usize) {
    let path = crate::support::repo().join(format!("lessons/{lesson_id}.toml"));
    let Ok(Document::Lesson(lesson)) = pipelens::lesson::load_file(&path) else {
        panic!("{lesson_id} loads");
    };
    let k = lesson
        .steps
        .iter()
        .position(|s| s.title.en == title && s.exercise.is_some())
        .unwrap_or_else(|| panic!("{lesson_id} has the lab {title}"));
    (*lesson, k)
}

/// The starter of step `k` with its TODO (from the labs' solutions) replaced by `code`: only the
/// file that holds the TODO is handed in, as a student's Save would hold it. `code` written as
/// `DECLARATIONS\n---\nBODY` also puts the declarations after the file's `#version` line (at
/// its top where it has none).
fn hand_in(lesson: &pipelens::lesson::Lesson, k: usize, code: &str) -> Code {
    let (top, code) = code.split_once("\n---\n").unwrap_or(("", code));
    let edit = |source: &str| {
        let body = source.replace(todo_of(lesson, k), code);
        match body.split_once('\n') {
            _ if top.is_empty() => body,
            Some((version, rest)) if version.starts_with("#version") => {
                format!("{version}\n{top}\n{rest}")
            }
            _ => format!("{top}\n{body}"),
        }
    };
    let todo = todo_of(lesson, k);
    let starter = &lesson.steps[k].exercise.as_ref().expect("a lab").starter;
    let mut out = Code::default();
    if let Some(sh) = &starter.shader {
        for (name, source) in [
            ("shader.vert", &sh.programs.vertex.source),
            ("shader.frag", &sh.programs.fragment.source),
        ] {
            if source.contains(todo) {
                out.take(name, edit(source));
            }
        }
    }
    for kind in pipeline::shader::HookKind::ALL {
        if let Some(h) = starter.hook(kind)
            && h.source.contains(todo)
        {
            out.take(&format!("{}.glsl", kind.key()), edit(&h.source));
        }
    }
    assert!(
        !out.is_empty(),
        "{}: the TODO {todo:?} is in no file",
        lesson.id
    );
    out
}

/// The line of step `k`'s starter that says TODO, as the labs' solutions replace it.
fn todo_of(lesson: &pipelens::lesson::Lesson, k: usize) -> &'static str {
    let title = &lesson.steps[k].title.en;
    SOLUTIONS
        .iter()
        .find(|(id, t, ..)| *id == lesson.id && t == title)
        .expect("the lab has a solution")
        .2
}

#[test]
fn every_lab_s_corpus_is_graded_as_a_teacher_would() {
    let mut wrong_per_lab = std::collections::BTreeMap::<(&str, &str), (usize, usize)>::new();
    let mut faults = Vec::new();
    for (lesson_id, title, code, want) in CORPUS {
        let (lesson, k) = lab(lesson_id, title);
        let g = grade(&lesson, k, &hand_in(&lesson, k, code), Lang::En);
        let said = g.sentences.join(" ");
        let counts = wrong_per_lab.entry((lesson_id, title)).or_default();
        match want {
            Right => {
                counts.1 += 1;
                if !g.passed {
                    faults.push(format!(
                        "{lesson_id} / {title}: a right answer fails: {said}\n{code}"
                    ));
                }
            }
            Wrong(words) => {
                counts.0 += 1;
                if g.passed {
                    faults.push(format!(
                        "{lesson_id} / {title}: a wrong answer passes:\n{code}"
                    ));
                } else if let Some(w) = words.iter().find(|w| !said.contains(**w)) {
                    faults.push(format!(
                        "{lesson_id} / {title}: {said:?} lacks {w:?}\n{code}"
                    ));
                }
                // Both languages say it.
                let zh = grade(&lesson, k, &hand_in(&lesson, k, code), Lang::Zh);
                assert_eq!(zh.passed, g.passed);
            }
        }
        eprintln!("{lesson_id} / {title}: {said}");
    }
    assert!(faults.is_empty(), "{}", faults.join("\n\n"));
    for ((lesson, title), (wrong, right)) in wrong_per_lab {
        assert!(
            wrong >= 3 && right >= 1,
            "{lesson} / {title}: {wrong} wrong and {right} right answers in the corpus"
        );
    }
}
