//! The corpus of the labs on transformations and rasterization (lessons 02–09, 25): hand-ins of the kinds students write,
//! wrong (each with the words its verdict must hold) and right (written otherwise than the
//! solution), graded by `lab_corpus`.

use crate::lab_corpus::Want::{self, Right, Wrong};

/// `(lesson, the lab's title, the code in place of the starter's TODO, what it should get)`.
pub(crate) const CORPUS: &[(&str, &str, &str, Want)] = &[
    // 02-arbitrary-axis: Lab: Rodrigues' formula.
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
    ("02-arbitrary-axis", "Lab: Rodrigues' formula", "    vec3 n = normalize(axis);
    float t = radians(deg);
    float c = cos(t);
    float s = sin(t);
    float k = 1.0 - c;
    return mat3(c + k * n.x * n.x, k * n.x * n.y + s * n.z, k * n.x * n.z - s * n.y,
                k * n.x * n.y - s * n.z, c + k * n.y * n.y, k * n.y * n.z + s * n.x,
                k * n.x * n.z + s * n.y, k * n.y * n.z - s * n.x, c + k * n.z * n.z);", Right),
    // 03-frames-lookat: Lab: LookAt from n, u, v.
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(at - eye);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                -dot(u, eye), -dot(v, eye), -dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `look_at()`", "pipelens' V but for"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, u.y, u.z, 0.0, v.x, v.y, v.z, 0.0, n.x, n.y, n.z, 0.0,
                -dot(u, eye), -dot(v, eye), -dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `look_at()`", "pipelens' V but for"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                dot(u, eye), dot(v, eye), dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `look_at()`", "pipelens' V but for"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(n, up));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                -dot(u, eye), -dot(v, eye), -dot(n, eye), 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `look_at()`", "pipelens' V but for"])),
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0, u.y, v.y, n.y, 0.0, u.z, v.z, n.z, 0.0,
                -eye.x, -eye.y, -eye.z, 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `look_at()`", "pipelens' V but for"])),
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
    ("03-frames-lookat", "Lab: LookAt from n, u, v", "    vec3 g = normalize(at - eye);
    vec3 r = normalize(cross(g, up));
    vec3 t = cross(r, g);
    mat4 rotation = mat4(r.x, t.x, -g.x, 0.0, r.y, t.y, -g.y, 0.0, r.z, t.z, -g.z, 0.0,
                         0.0, 0.0, 0.0, 1.0);
    mat4 translation = mat4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
                            -eye.x, -eye.y, -eye.z, 1.0);
    return rotation * translation;", Right),
    // 06-clipping-ndc-viewport: Lab: the viewport matrix.
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w, 0.0, 0.0, 0.0, 0.0, h, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0,
                w / 2.0, h / 2.0, 0.5, 1.0);", Wrong(&["Not yet", "Your `viewport()`", "pipelens' M_viewport but for"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, 0.0, 0.0, h / 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
                w / 2.0, h / 2.0, 0.0, 1.0);", Wrong(&["Not yet", "Your `viewport()`", "pipelens' M_viewport but for"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, w / 2.0, 0.0, h / 2.0, 0.0, h / 2.0, 0.0, 0.0, 0.5, 0.5,
                0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "Your `viewport()`", "pipelens' M_viewport but for"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, 0.0, 0.0, -h / 2.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0,
                w / 2.0, h / 2.0, 0.5, 1.0);", Wrong(&["Not yet", "Your `viewport()`", "pipelens' M_viewport but for"])),
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    return mat4(w / 2.0, 0.0, 0.0, 0.0, 0.0, h / 2.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0,
                w / 2.0 - 0.5, h / 2.0 - 0.5, 0.5, 1.0);", Wrong(&["Not yet", "Your `viewport()`", "pipelens' M_viewport but for"])),
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
    ("06-clipping-ndc-viewport", "Lab: the viewport matrix", "    vec3 half_size = vec3(w, h, 1.0) / 2.0;
    return mat4(vec4(half_size.x, 0.0, 0.0, 0.0), vec4(0.0, half_size.y, 0.0, 0.0),
                vec4(0.0, 0.0, half_size.z, 0.0), vec4(half_size, 1.0));", Right),
    // 07-rasterization: Lab: the inside test.
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
    ("07-rasterization", "Lab: the inside test", "    vec2 corner[3] = vec2[3](a, b, c);
    for (int i = 0; i < 3; i++) {
        vec2 from = corner[i];
        vec2 to = corner[(i + 1) % 3];
        float e = edge(from, to, p);
        bool top_left = (to.y == from.y && to.x < from.x) || to.y < from.y;
        if (e < 0.0 || (e == 0.0 && !top_left)) {
            return false;
        }
    }
    return true;", Right),
    // 08-antialiasing: Lab: the inside test at every sample.
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
    ("08-antialiasing", "Lab: the inside test at every sample", "    return edge(a, b, p) >= 0.0 && edge(b, c, p) >= 0.0 && edge(c, a, p) >= 0.0;", Wrong(&["Not yet", "your inside()", "(on it"])),
    ("08-antialiasing", "Lab: the inside test at every sample", "    return edge(a, b, p) > 0.0 && edge(b, c, p) > 0.0 && edge(c, a, p) > 0.0;", Wrong(&["Not yet", "your inside()", "(on it"])),
    ("08-antialiasing", "Lab: the inside test at every sample", "    vec2 corner[3] = vec2[3](a, b, c);
    for (int i = 0; i < 3; i++) {
        vec2 from = corner[i];
        vec2 to = corner[(i + 1) % 3];
        float e = edge(from, to, p);
        bool top_left = (to.y == from.y && to.x < from.x) || to.y < from.y;
        if (e < 0.0 || (e == 0.0 && !top_left)) {
            return false;
        }
    }
    return true;", Right),
    ("08-antialiasing", "Lab: the inside test at every sample", "float edge_of(vec2 a, vec2 b, vec2 p) {
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
    // 09-z-buffer: Lab: the depth test.
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
    // 25-lab-model-projection: Lab: the rotation about z.
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    return mat4(cos(t), -sin(t), 0.0, 0.0, sin(t), cos(t), 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `rotate_z()`", "pipelens' M but for"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = deg;
    return mat4(cos(t), sin(t), 0.0, 0.0, -sin(t), cos(t), 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `rotate_z()`", "pipelens' M but for"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    return mat4(1.0, 0.0, 0.0, 0.0, 0.0, cos(t), sin(t), 0.0, 0.0, -sin(t), cos(t), 0.0, 0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `rotate_z()`", "pipelens' M but for"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    return mat4(vec4(cos(t), sin(t), 0.0, 0.0), vec4(-sin(t), cos(t), 0.0, 0.0), vec4(0.0, 0.0, 1.0, 0.0), vec4(0.0, 0.0, 0.0, 1.0));", Right),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    float c = cos(t);
    float s = sin(t);
    return mat4(c, 0.0, -s, 0.0, 0.0, 1.0, 0.0, 0.0, s, 0.0, c, 0.0, 0.0, 0.0, 0.0, 1.0);", Wrong(&["Not yet", "The first vertex off", "Your `rotate_z()`"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = radians(deg);
    float c = cos(t);
    float s = sin(t);
    return mat4(c, s, 0.0, 0.0, -s, c, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0);", Wrong(&["Not yet", "Your `rotate_z()`"])),
    ("25-lab-model-projection", "Lab: the rotation about z", "    mat4 r = mat4(1.0);
    float t = radians(deg);
    r[0].xy = vec2(cos(t), sin(t));
    r[1].xy = vec2(-sin(t), cos(t));
    return r;", Right),
    ("25-lab-model-projection", "Lab: the rotation about z", "    float t = deg * 3.14159265 / 180.0;
    return mat4(vec4(cos(t), sin(t), 0.0, 0.0), vec4(-sin(t), cos(t), 0.0, 0.0),
                vec4(0.0, 0.0, 1.0, 0.0), vec4(0.0, 0.0, 0.0, 1.0));", Right),
    // 25-lab-model-projection: Lab: the perspective projection.
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), 1.0,
                0.0, 0.0, 2.0 * zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet", "Your `perspective()`", "pipelens' P but for"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy));
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), -1.0,
                0.0, 0.0, 2.0 * zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet", "Your `perspective()`", "pipelens' P but for"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f, 0.0, 0.0, 0.0, 0.0, f / aspect, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), -1.0,
                0.0, 0.0, 2.0 * zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet", "Your `perspective()`", "pipelens' P but for"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "uniform mat4 projection;
---
    return projection;", Wrong(&["declares pipelens' own `projection`"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), -1.0,
                0.0, 0.0, zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet", "lie at another depth", "Your `perspective()`"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0,
                0.0, 0.0, zFar / (zNear - zFar), -1.0,
                0.0, 0.0, zFar * zNear / (zNear - zFar), 0.0);", Wrong(&["Not yet", "lie at another depth", "Your `perspective()`"])),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float t = radians(fovy) * 0.5;
    float f = cos(t) / sin(t);
    float nf = zNear - zFar;
    return mat4(vec4(f / aspect, 0, 0, 0), vec4(0, f, 0, 0), vec4(0, 0, (zNear + zFar) / nf, -1), vec4(0, 0, 2.0 * zNear * zFar / nf, 0));", Right),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float top = zNear * tan(radians(fovy / 2.0));
    float right = top * aspect;
    return mat4(zNear / right, 0, 0, 0,  0, zNear / top, 0, 0,  0, 0, -(zFar + zNear) / (zFar - zNear), -1,  0, 0, -2.0 * zFar * zNear / (zFar - zNear), 0);", Right),
    ("25-lab-model-projection", "Lab: the perspective projection", "    float top = zNear * tan(radians(fovy) / 2.0);
    float right = top * aspect;
    return mat4(zNear / right, 0.0, 0.0, 0.0,
                0.0, zNear / top, 0.0, 0.0,
                0.0, 0.0, -(zFar + zNear) / (zFar - zNear), -1.0,
                0.0, 0.0, -2.0 * zFar * zNear / (zFar - zNear), 0.0);", Right),
];
