//! Each lab's reference solution, kept here and not in the lesson: the lesson, the step's
//! title, the starter's `TODO` line, and the code that replaces it.

/// The inside test with the top-left rule, the solution of both inside-test labs (07 and 08):
/// each edge's `E ≥ 0`, a tie inside only on a top or left edge.
const TOP_LEFT_INSIDE: &str = "    vec2 corner[3] = vec2[3](a, b, c);
    for (int i = 0; i < 3; i++) {
        vec2 from = corner[i];
        vec2 to = corner[(i + 1) % 3];
        float e = edge(from, to, p);
        bool top_left = (to.y == from.y && to.x < from.x) || to.y < from.y;
        if (e < 0.0 || (e == 0.0 && !top_left)) {
            return false;
        }
    }
    return true;";

/// Each lab's solution: the lesson, the step's title, and the starter's `TODO` line replaced.
pub(crate) const SOLUTIONS: &[(&str, &str, &str, &str)] = &[
    (
        "11-shading-frequencies",
        "Lab: the normal matrix",
        "    // TODO: the inverse transpose of m's upper-left 3×3 block. (As written: m's block itself.)
    return mat3(m);",
        "    return transpose(inverse(mat3(m)));",
    ),
    (
        "14-mipmaps",
        "Lab: the level of detail from the derivatives",
        "    // TODO: L from dFdx(uv) and dFdy(uv) in texels, then λ = log2(L). (As written: level 0.)
    return 0.0;",
        "    float lx = length(dFdx(uv) * size);
    float ly = length(dFdy(uv) * size);
    return log2(max(max(lx, ly), 1e-12));",
    ),
    (
        "15-surface-detail",
        "Lab: the bump map in a fragment shader",
        "        // TODO: dU and dV from the height one texel to the right and one texel up, times
        // bump_strength; then local = (−dU, −dV, 1). (As written, the normal is not tilted.)
        local = vec3(0.0, 0.0, 1.0);",
        "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0 / size.x, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0 / size.y)) - here);
        local = vec3(-du, -dv, 1.0);",
    ),
    (
        "12-interpolation",
        "Lab: the 1/w weights",
        "    // TODO: u/w, v/w and 1/w, with w = clip.w. (As written: u, v and 1, the affine blend.)
    uv_over_w = uv;
    one_over_w = 1.0;",
        "    uv_over_w = uv / clip.w;
    one_over_w = 1.0 / clip.w;",
    ),
    (
        "13-texture-mapping",
        "Lab: bilinear filtering from texelFetch",
        "    // TODO: the four texels around (x, y) and their weights. (This reads the nearest one.)
    return texel(ivec2(floor(uv * vec2(size))));",
        "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    vec2 st = xy - f;
    ivec2 ij = ivec2(f);
    vec3 bottom = mix(texel(ij), texel(ij + ivec2(1, 0)), st.x);
    vec3 top = mix(texel(ij + ivec2(0, 1)), texel(ij + ivec2(1, 1)), st.x);
    return mix(bottom, top, st.y);",
    ),
    (
        "02-arbitrary-axis",
        "Lab: Rodrigues' formula",
        "    // TODO: n of length 1, then the three terms (mat3 takes its numbers column by column).
    return mat3(1.0);",
        "    vec3 n = normalize(axis);
    float t = radians(deg);
    mat3 cross_n = mat3(0.0, n.z, -n.y, -n.z, 0.0, n.x, n.y, -n.x, 0.0);
    return cos(t) * mat3(1.0) + (1.0 - cos(t)) * outerProduct(n, n) + sin(t) * cross_n;",
    ),
    (
        "03-frames-lookat",
        "Lab: LookAt from n, u, v",
        "    // TODO: n, u, v, then the matrix (mat4 takes its numbers column by column).
    return mat4(1.0);",
        "    vec3 n = normalize(eye - at);
    vec3 u = normalize(cross(up, n));
    vec3 v = cross(n, u);
    return mat4(u.x, v.x, n.x, 0.0,
                u.y, v.y, n.y, 0.0,
                u.z, v.z, n.z, 0.0,
                -dot(u, eye), -dot(v, eye), -dot(n, eye), 1.0);",
    ),
    (
        "18-bezier",
        "Lab: de Casteljau",
        "    // TODO: three levels: 4 points → 3 → 2 → 1. (As written: the first point of the first level.)
    return lerp(p0, p1, t);",
        "    vec2 a = lerp(p0, p1, t);
    vec2 b = lerp(p1, p2, t);
    vec2 c = lerp(p2, p3, t);
    vec2 d = lerp(a, b, t);
    vec2 e = lerp(b, c, t);
    return lerp(d, e, t);",
    ),
    (
        "25-lab-model-projection",
        "Lab: the rotation about z",
        "    // TODO: the rotation about z (mat4 takes its numbers column by column).
    return mat4(1.0);",
        "    float t = radians(deg);
    float c = cos(t);
    float s = sin(t);
    return mat4(c, s, 0.0, 0.0, -s, c, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);",
    ),
    (
        "25-lab-model-projection",
        "Lab: the perspective projection",
        "    // TODO: the perspective matrix (mat4 takes its numbers column by column).
    return mat4(1.0);",
        "    float f = 1.0 / tan(radians(fovy) / 2.0);
    return mat4(f / aspect, 0.0, 0.0, 0.0,
                0.0, f, 0.0, 0.0,
                0.0, 0.0, (zFar + zNear) / (zNear - zFar), -1.0,
                0.0, 0.0, 2.0 * zFar * zNear / (zNear - zFar), 0.0);",
    ),
    (
        "06-clipping-ndc-viewport",
        "Lab: the viewport matrix",
        "    // TODO: the viewport matrix (mat4 takes its numbers column by column).
    return mat4(1.0);",
        "    return mat4(w / 2.0, 0.0, 0.0, 0.0,
                0.0, h / 2.0, 0.0, 0.0,
                0.0, 0.0, 0.5, 0.0,
                w / 2.0, h / 2.0, 0.5, 1.0);",
    ),
    (
        "07-rasterization",
        "Lab: the inside test",
        "    // TODO: all three edges, and a tie (edge = 0.0) inside only on a top edge
    // (b.y == a.y, going left) or a left edge (going down).
    return edge(a, b, p) >= 0.0;",
        TOP_LEFT_INSIDE,
    ),
    (
        "08-antialiasing",
        "Lab: the inside test at every sample",
        "    // TODO: test the sample p itself. (As written: the pixel's centre, for all its samples.)
    vec2 q = floor(p) + 0.5;
    return edge(a, b, q) >= 0.0 && edge(b, c, q) >= 0.0 && edge(c, a, q) >= 0.0;",
        TOP_LEFT_INSIDE,
    ),
    (
        "15-surface-detail",
        "Lab: displacement in a vertex shader",
        "    // TODO: move the vertex along its normal by k·h(u, v). (As written: it stays where it was.)
    vec3 p = position;",
        "    vec3 p = position + normal * (displacement_scale * height(uv));",
    ),
    (
        "15-surface-detail",
        "Lab: a mirror in a fragment shader",
        "    // TODO: look the surroundings up in the mirror direction r and mix them in with
    // k = reflectivity. (As written: the ball is lit, but it reflects nothing.)
    color = vec4(own + specular, 1.0);",
        "    vec3 r = reflect(-v, n);
    float k = reflectivity;
    color = vec4((1.0 - k) * own + specular + k * texture(environment, r).rgb, 1.0);",
    ),
    (
        "19-bezier-surfaces",
        "Lab: the patch by de Casteljau",
        "    // TODO: Q_0 … Q_3 at u, then their curve at v. (As written: the corner P00 for every (u, v).)
    return p[0];",
        "    vec3 q0 = de_casteljau(p[0], p[1], p[2], p[3], u);
    vec3 q1 = de_casteljau(p[4], p[5], p[6], p[7], u);
    vec3 q2 = de_casteljau(p[8], p[9], p[10], p[11], u);
    vec3 q3 = de_casteljau(p[12], p[13], p[14], p[15], u);
    return de_casteljau(q0, q1, q2, q3, v);",
    ),
    (
        "16-planar-shadows",
        "Lab: the shadow matrix",
        "    // TODO: T(−l), P and T(l). (As written: three identities, so the shadow is the object.)",
        "    to_light[3] = vec4(-light, 1.0);
    project[1][3] = -1.0 / light.y;
    project[3][3] = 0.0;
    back[3] = vec4(light, 1.0);",
    ),
    (
        "09-z-buffer",
        "Lab: the depth test",
        "    // TODO: write the sample only when this fragment is nearer than what is stored.
    return true;",
        "    return z < stored;",
    ),
    (
        "10-blinn-phong",
        "Lab: the specular term in a fragment shader",
        "        // TODO: the specular term, where n·l > 0.",
        "        vec3 h = normalize(l + v);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }",
    ),
    (
        "10-blinn-phong",
        "Lab: light casters",
        "        // TODO: l and f for each kind: a distant light (LIGHT_DIRECTIONAL) and a spot light's
        // cone (LIGHT_SPOT). (As written: every light is a point light.)
        vec3 to_light = light.position - w_pos;
        float d = length(to_light);
        vec3 l = normalize(to_light);
        vec3 abc = light.attenuation;
        float f = 1.0 / (abc.x + abc.y * d + abc.z * d * d);",
        "        vec3 l;
        float f = 1.0;
        if (light.kind == LIGHT_DIRECTIONAL) {
            l = normalize(-light.direction);
        } else {
            vec3 to_light = light.position - w_pos;
            float d = length(to_light);
            l = normalize(to_light);
            vec3 abc = light.attenuation;
            f = 1.0 / (abc.x + abc.y * d + abc.z * d * d);
            if (light.kind == LIGHT_SPOT) {
                float cos_phi = dot(-l, normalize(light.direction));
                f *= cos_phi < light.cutoff_cos ? 0.0 : pow(max(cos_phi, 0.0), light.exponent);
            }
        }",
    ),
    (
        "24-shader-programs",
        "Lab: the texture as k_d's colour",
        "    // TODO: c, the surface colour, from the texture at v_uv. (As written: the object's colour.)
    vec3 c = v_color;",
        "    vec3 c = texture(tex, v_uv).rgb;",
    ),
    (
        "24-shader-programs",
        "Lab: Gouraud shading in the vertex shader",
        "    // TODO: add this vertex's diffuse term to lit, and its specular term to specular where n·l > 0.",
        "    vec3 l = normalize(light_pos - p);
    vec3 h = normalize(l + v);
    lit += kd * c * light_color * max(dot(n, l), 0.0);
    if (dot(n, l) > 0.0) {
        specular += ks * light_color * pow(max(dot(n, h), 0.0), shininess);
    }",
    ),
    (
        "24-shader-programs",
        "Lab: the diffuse term",
        "    // TODO: the diffuse term k_d·c·I·max(n·l, 0), added to L.",
        "    L += kd * v_color * light_color * max(dot(n, l), 0.0);",
    ),
];
