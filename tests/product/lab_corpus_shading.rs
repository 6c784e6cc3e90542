//! The corpus of the labs on shading, texturing and curves (lessons 10–24): hand-ins of the kinds students write,
//! wrong (each with the words its verdict must hold) and right (written otherwise than the
//! solution), graded by `lab_corpus`.

use crate::lab_corpus::Want::{self, Right, Wrong};

/// `(lesson, the lab's title, the code in place of the starter's TODO, what it should get)`.
pub(crate) const CORPUS: &[(&str, &str, &str, Want)] = &[
    // 10-blinn-phong: Lab: light casters.
    ("10-blinn-phong", "Lab: light casters", "        vec3 l;
        float f = 1.0;
        if (light.kind == LIGHT_DIRECTIONAL) {
            l = normalize(light.direction);
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
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: light casters", "        vec3 l;
        float f = 1.0;
        if (light.kind == LIGHT_DIRECTIONAL) {
            l = normalize(-light.direction);
            float d = length(w_pos);
            vec3 abc = light.attenuation;
            f = 1.0 / (abc.x + abc.y * d + abc.z * d * d + 0.5 * d);
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
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: light casters", "        vec3 l;
        float f = 1.0;
        if (light.kind == LIGHT_DIRECTIONAL) {
            l = normalize(-light.direction);
        } else {
            vec3 to_light = light.position - w_pos;
            float d = length(to_light);
            l = normalize(to_light);
            vec3 abc = light.attenuation;
            f = 1.0 / (abc.x + abc.y * d + abc.z * d * d);
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: light casters", "        vec3 l;
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
                float cos_phi = dot(l, normalize(light.direction));
                f *= cos_phi < light.cutoff_cos ? 0.0 : pow(max(cos_phi, 0.0), light.exponent);
            }
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: light casters", "        vec3 l;
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
                f *= cos_phi < light.cutoff_cos ? 0.0 : 1.0;
            }
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: light casters", "        vec3 l;
        float f = 1.0;
        if (light.kind == LIGHT_DIRECTIONAL) {
            l = normalize(-light.direction);
        } else {
            l = normalize(light.position - w_pos);
            if (light.kind == LIGHT_SPOT) {
                float cos_phi = dot(-l, normalize(light.direction));
                f = cos_phi < light.cutoff_cos ? 0.0 : pow(max(cos_phi, 0.0), light.exponent);
            } else {
                float d = length(light.position - w_pos);
                vec3 abc = light.attenuation;
                f = 1.0 / (abc.x + abc.y * d + abc.z * d * d);
            }
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: light casters", "        vec3 l = light.kind == LIGHT_DIRECTIONAL ? normalize(-light.direction) : normalize(light.position - w_pos);
        float f = 1.0;
        if (light.kind != LIGHT_DIRECTIONAL) {
            float d = distance(light.position, w_pos);
            f = 1.0 / dot(light.attenuation, vec3(1.0, d, d * d));
        }
        if (light.kind == LIGHT_SPOT) {
            float cos_phi = dot(-l, normalize(light.direction));
            f *= step(light.cutoff_cos, cos_phi) * pow(max(cos_phi, 0.0), light.exponent);
        }", Right),
    ("10-blinn-phong", "Lab: light casters", "float falloff(vec3 abc, float d) {
    return 1.0 / (abc.x + d * (abc.y + d * abc.z));
}
float cone(vec3 axis, vec3 l, float cutoff_cos, float e) {
    float cos_phi = dot(-l, normalize(axis));
    if (cos_phi < cutoff_cos) {
        return 0.0;
    }
    return pow(cos_phi, e);
}
---
        vec3 l = normalize(-light.direction);
        float f = 1.0;
        if (light.kind == LIGHT_POINT || light.kind == LIGHT_SPOT) {
            vec3 to_light = light.position - w_pos;
            l = to_light / length(to_light);
            f = falloff(light.attenuation, length(to_light));
        }
        if (light.kind == LIGHT_SPOT) {
            f = f * cone(light.direction, l, light.cutoff_cos, light.exponent);
        }", Right),
    ("10-blinn-phong", "Lab: light casters", "        bool distant = light.kind == LIGHT_DIRECTIONAL;
        vec3 to_light = light.position - w_pos;
        float d = length(to_light);
        vec3 l = distant ? -normalize(light.direction) : to_light / d;
        vec3 abc = light.attenuation;
        float f = distant ? 1.0 : 1.0 / (abc.x + abc.y * d + abc.z * d * d);
        float cos_phi = dot(-l, normalize(light.direction));
        if (light.kind == LIGHT_SPOT && cos_phi < light.cutoff_cos) {
            f = 0.0;
        } else if (light.kind == LIGHT_SPOT) {
            f *= pow(cos_phi, light.exponent);
        }", Right),
    // 10-blinn-phong: Lab: the specular term in a fragment shader.
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = normalize(l + v);
        sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 r = reflect(-l, n);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(r, v), 0.0), shininess);
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = normalize(l + v);
        if (n_dot_l > 0.0) {
            sum += ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = l + v;
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 h = normalize(l + v);
        if (n_dot_l > 0.0) {
            sum += f * ks * c * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        vec3 half_vector = (l + v) / length(l + v);
        float lit = n_dot_l > 0.0 ? 1.0 : 0.0;
        sum += lit * f * light.intensity * ks * pow(max(dot(half_vector, n), 0.0), shininess);", Right),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        if (n_dot_l <= 0.0) {
            continue;
        }
        vec3 h = normalize(v + l);
        float spec = pow(max(dot(h, n), 0.0), shininess);
        sum += spec * ks * light.intensity * f;", Right),
    ("10-blinn-phong", "Lab: the specular term in a fragment shader", "        float gate = n_dot_l > 0.0 ? 1.0 : 0.0;
        vec3 h = (l + v) / length(l + v);
        sum += gate * f * ks * light.intensity * pow(clamp(dot(n, h), 0.0, 1.0), shininess);", Right),
    // 11-shading-frequencies: Lab: the normal matrix.
    ("11-shading-frequencies", "Lab: the normal matrix", "    return inverse(mat3(m));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return transpose(mat3(m));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return mat3(transpose(m));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return -transpose(inverse(mat3(m)));", Wrong(&["Not yet", "your vertex shader's `w_nrm`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "uniform mat3 normal_matrix;
---
    return normal_matrix;", Wrong(&["declares pipelens' own `normal_matrix`"])),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return mat3(transpose(inverse(m)));", Right),
    ("11-shading-frequencies", "Lab: the normal matrix", "    return 2.0 * inverse(transpose(mat3(m)));", Right),
    ("11-shading-frequencies", "Lab: the normal matrix", "    mat3 a = mat3(m);
    return mat3(cross(a[1], a[2]), cross(a[2], a[0]), cross(a[0], a[1])) / determinant(a);", Right),
    // 12-interpolation: Lab: the 1/w weights.
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv * clip.w;
    one_over_w = clip.w;", Wrong(&["Not yet", "your `uv`", "interpolated perspective-correctly"])),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv / clip.w;
    one_over_w = 1.0;", Wrong(&["Not yet", "your `uv`", "interpolated perspective-correctly"])),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv / clip.z;
    one_over_w = 1.0 / clip.z;", Wrong(&["Not yet", "your `uv`", "interpolated perspective-correctly"])),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv;
    one_over_w = 1.0 / clip.w;", Wrong(&["Not yet", "your `uv`", "interpolated perspective-correctly"])),
    ("12-interpolation", "Lab: the 1/w weights", "    float inv = 1.0 / clip.w;
    uv_over_w = uv * inv;
    one_over_w = inv;", Right),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = uv / clip.w;
    one_over_w = 1.0 / clip.z;", Wrong(&["Not yet", "your `uv`", "interpolated perspective-correctly"])),
    ("12-interpolation", "Lab: the 1/w weights", "    float w = clip.w;
    uv_over_w = uv * (1.0 / w);
    one_over_w = 1.0 / w;", Right),
    ("12-interpolation", "Lab: the 1/w weights", "    uv_over_w = 2.0 * uv / clip.w;
    one_over_w = 2.0 / clip.w;", Right),
    // 13-texture-mapping: Lab: bilinear filtering from texelFetch.
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size);
    vec2 f = floor(xy);
    vec2 st = xy - f;
    ivec2 ij = ivec2(f);
    vec3 bottom = mix(texel(ij), texel(ij + ivec2(1, 0)), st.x);
    vec3 top = mix(texel(ij + ivec2(0, 1)), texel(ij + ivec2(1, 1)), st.x);
    return mix(bottom, top, st.y);", Wrong(&["Not yet", "your `bilinear()`", "between texels"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    vec2 st = xy - f;
    ivec2 ij = ivec2(f);
    vec3 bottom = mix(texel(ij), texel(ij + ivec2(1, 0)), st.y);
    vec3 top = mix(texel(ij + ivec2(0, 1)), texel(ij + ivec2(1, 1)), st.x);
    return mix(bottom, top, st.x);", Wrong(&["Not yet", "your `bilinear()`", "between texels"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    ivec2 ij = ivec2(xy);
    vec2 st = xy - vec2(ij);
    vec3 bottom = mix(texel(ij), texel(ij + ivec2(1, 0)), st.x);
    vec3 top = mix(texel(ij + ivec2(0, 1)), texel(ij + ivec2(1, 1)), st.x);
    return mix(bottom, top, st.y);", Wrong(&["Not yet", "your `bilinear()`", "between texels"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    ivec2 ij = ivec2(f);
    return (texel(ij) + texel(ij + ivec2(1, 0)) + texel(ij + ivec2(0, 1)) + texel(ij + ivec2(1, 1))) / 4.0;", Wrong(&["Not yet", "your `bilinear()`", "between texels"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    return texture(tex, uv).rgb;", Wrong(&["calls `texture()`"])),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    float s = xy.x - f.x;
    float t = xy.y - f.y;
    ivec2 ij = ivec2(f);
    return (1.0 - s) * (1.0 - t) * texel(ij) + s * (1.0 - t) * texel(ij + ivec2(1, 0))
         + (1.0 - s) * t * texel(ij + ivec2(0, 1)) + s * t * texel(ij + ivec2(1, 1));", Right),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    ivec2 ij = ivec2(floor(xy));
    float s = fract(xy.x);
    float t = fract(xy.y);
    vec3 sum = (1.0 - s) * (1.0 - t) * texel(ij);
    sum += s * (1.0 - t) * texel(ij + ivec2(1, 0));
    sum += (1.0 - s) * t * texel(ij + ivec2(0, 1));
    sum += s * t * texel(ij + ivec2(1, 1));
    return sum;", Right),
    ("13-texture-mapping", "Lab: bilinear filtering from texelFetch", "    vec2 xy = uv * vec2(size) - 0.5;
    vec2 f = floor(xy);
    vec2 st = xy - f;
    vec3 sum = vec3(0.0);
    for (int dj = 0; dj < 2; dj++) {
        for (int di = 0; di < 2; di++) {
            float wx = di == 0 ? 1.0 - st.x : st.x;
            float wy = dj == 0 ? 1.0 - st.y : st.y;
            sum += wx * wy * texel(ivec2(f) + ivec2(di, dj));
        }
    }
    return sum;", Right),
    // 14-mipmaps: Lab: the level of detail from the derivatives.
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv));
    float ly = length(dFdy(uv));
    return log2(max(max(lx, ly), 1e-12));", Wrong(&["Not yet", "your `level_of_detail()`", "pipelens' λ there"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv) * size);
    float ly = length(dFdy(uv) * size);
    return log2(min(lx, ly));", Wrong(&["Not yet", "your `level_of_detail()`", "pipelens' λ there"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv) * size);
    float ly = length(dFdy(uv) * size);
    return max(lx, ly);", Wrong(&["Not yet", "your `level_of_detail()`", "pipelens' λ there"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv) * size);
    float ly = length(dFdy(uv) * size);
    return log2(max(lx, ly)) + 1.0;", Wrong(&["Not yet", "your `level_of_detail()`", "pipelens' λ there"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    vec2 dx = dFdx(uv) * size;
    vec2 dy = dFdy(uv) * size;
    return 0.5 * log2(max(max(dot(dx, dx), dot(dy, dy)), 1e-24));", Right),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    float lx = length(dFdx(uv) * size.x);
    float ly = length(dFdy(uv) * size.y);
    return log2(max(lx, ly));", Wrong(&["Not yet", "your `level_of_detail()`", "pipelens' λ there"])),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    vec2 dx = dFdx(uv * size);
    vec2 dy = dFdy(uv * size);
    return log2(max(length(dx), length(dy)));", Right),
    ("14-mipmaps", "Lab: the level of detail from the derivatives", "    return max(log2(length(dFdx(uv) * size)), log2(length(dFdy(uv) * size)));", Right),
    // 15-surface-detail: Lab: the bump map in a fragment shader.
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0 / size.y, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0 / size.x)) - here);
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = height(uv + vec2(1.0 / size.x, 0.0)) - here;
        float dv = height(uv + vec2(0.0, 1.0 / size.y)) - here;
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0 / size.x, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0 / size.y)) - here);
        local = vec3(du, dv, 1.0);", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = textureLod(detail, uv, 0.0).r;
        float du = bump_strength * (textureLod(detail, uv + vec2(1.0 / size.x, 0.0), 0.0).r - here);
        float dv = bump_strength * (textureLod(detail, uv + vec2(0.0, 1.0 / size.y), 0.0).r - here);
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0)) - here);
        local = vec3(-du, -dv, 1.0);", Wrong(&["Not yet", "At the inspected pixel ("])),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 texel_step = 1.0 / vec2(textureSize(detail, 0));
        float h0 = height(uv);
        vec2 d = bump_strength * (vec2(height(uv + vec2(texel_step.x, 0.0)), height(uv + vec2(0.0, texel_step.y))) - h0);
        local = vec3(-d, 1.0);", Right),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        float h0 = height(uv);
        vec2 texel_size = vec2(1.0) / vec2(textureSize(detail, 0));
        float du = height(uv + vec2(texel_size.x, 0.0)) - h0;
        float dv = height(uv + vec2(0.0, texel_size.y)) - h0;
        local = vec3(-du, -dv, 1.0) * vec3(bump_strength, bump_strength, 1.0);", Right),
    ("15-surface-detail", "Lab: the bump map in a fragment shader", "        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0 / size.x, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0 / size.y)) - here);
        local = 2.0 * vec3(-du, -dv, 1.0);", Right),
    // 15-surface-detail: Lab: displacement in a vertex shader.
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position + normal * (displacement_scale * textureLod(displacement, uv, 0.0).r);", Wrong(&["Not yet", "The first vertex off"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position + normal * height(uv);", Wrong(&["Not yet", "The first vertex off"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position - normal * (displacement_scale * height(uv));", Wrong(&["Not yet", "The first vertex off"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position + normal * (displacement_scale * height(uv.yx));", Wrong(&["Not yet", "The first vertex off"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    float k = displacement_scale;
    vec3 p = position;
    p += k * height(uv) * normal;", Right),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = position + normal * displacement_scale;", Wrong(&["Not yet", "The first vertex off"])),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    vec3 p = mix(position, position + normal, displacement_scale * height(uv));", Right),
    ("15-surface-detail", "Lab: displacement in a vertex shader", "    float lifted = displacement_scale * height(uv);
    vec3 p = position;
    p.x += lifted * normal.x;
    p.y += lifted * normal.y;
    p.z += lifted * normal.z;", Right),
    // 15-surface-detail: Lab: a mirror in a fragment shader. GLSL's reflect(I, n) takes I from
    // the eye: reflect(v, n) mirrors the wrong way; a direction need not be unit long.
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    vec3 r = reflect(v, n);
    float k = reflectivity;
    color = vec4((1.0 - k) * own + specular + k * texture(environment, r).rgb, 1.0);", Wrong(&["Not yet", "your `r`"])),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    vec3 r = reflect(-eye, n);
    float k = reflectivity;
    color = vec4((1.0 - k) * own + specular + k * texture(environment, r).rgb, 1.0);", Wrong(&["Not yet", "your `r`"])),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    vec3 r = refract(-v, n, 1.0 / 1.5);
    float k = reflectivity;
    color = vec4((1.0 - k) * own + specular + k * texture(environment, r).rgb, 1.0);", Wrong(&["Not yet", "your `r`"])),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    vec3 r = reflect(-v, n);
    color = vec4(own + specular + reflectivity * texture(environment, r).rgb, 1.0);", Wrong(&["Not yet", "your `color`"])),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    vec3 r = reflect(-v, n);
    color = vec4(mix(own + specular, texture(environment, r).rgb, reflectivity), 1.0);", Wrong(&["Not yet", "your `color`"])),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    float k = reflectivity;
    color = vec4((1.0 - k) * own + specular + k * texture(environment, n).rgb, 1.0);", Wrong(&["Not yet", "your `color`"])),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    vec3 r = 2.0 * dot(n, v) * n - v;
    vec3 env = texture(environment, r).rgb;
    color = vec4(own * (1.0 - reflectivity) + env * reflectivity + specular, 1.0);", Right),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "    vec3 seen = texture(environment, reflect(w_pos - eye, n)).rgb;
    color = vec4(mix(own, seen, reflectivity) + specular, 1.0);", Right),
    ("15-surface-detail", "Lab: a mirror in a fragment shader", "vec3 mirrored(vec3 towards_eye, vec3 normal) {
    return normalize(2.0 * dot(normal, towards_eye) * normal - towards_eye);
}
---
    color = vec4(own + specular, 1.0);
    color.rgb += reflectivity * (texture(environment, mirrored(v, n)).rgb - own);", Right),
    // 16-planar-shadows: Lab: the shadow matrix.
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
    ("16-planar-shadows", "Lab: the shadow matrix", "    to_light[3] = vec4(-light, 1.0);
    project[1][3] = -1.0 / light.y;
    project[3][3] = 0.0;", Wrong(&["Not yet", "M_shadow"])),
    ("16-planar-shadows", "Lab: the shadow matrix", "    to_light[3].xyz = -light;
    project[1].w = -1.0 / light.y;
    project[3].w = 0.0;
    back[3].xyz = light;", Right),
    ("16-planar-shadows", "Lab: the shadow matrix", "    for (int i = 0; i < 3; i++) {
        to_light[3][i] = -light[i];
        back[3][i] = light[i];
    }
    project[1][3] = -1.0 / light.y;
    project[3][3] = 0.0;", Right),
    // 18-bezier: Lab: de Casteljau.
    ("18-bezier", "Lab: de Casteljau", "    vec2 a = lerp(p0, p1, t);
    vec2 b = lerp(p1, p2, t);
    vec2 c = lerp(p2, p3, t);
    return lerp(a, c, t);", Wrong(&["Not yet", "The first, t ="])),
    ("18-bezier", "Lab: de Casteljau", "    vec2 a = lerp(p0, p1, t);
    vec2 b = lerp(p1, p2, t);
    vec2 c = lerp(p2, p3, t);
    vec2 d = lerp(a, b, t);
    vec2 e = lerp(b, c, t);
    return lerp(d, e, 1.0 - t);", Wrong(&["Not yet", "The first, t ="])),
    ("18-bezier", "Lab: de Casteljau", "    return lerp(p0, p3, t);", Wrong(&["Not yet", "The first, t ="])),
    ("18-bezier", "Lab: de Casteljau", "    float s = 1.0 - t;
    return s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;", Right),
    ("18-bezier", "Lab: de Casteljau", "    vec2 p[4] = vec2[4](p0, p1, p2, p3);
    for (int level = 3; level > 0; level--) {
        for (int i = 0; i < level; i++) {
            p[i] = mix(p[i], p[i + 1], t);
        }
    }
    return p[0];", Right),
    ("18-bezier", "Lab: de Casteljau", "    float s = 1.0 - t;
    return s * s * s * p0 + s * s * t * p1 + s * t * t * p2 + t * t * t * p3;", Wrong(&["Not yet", "The first, t ="])),
    ("18-bezier", "Lab: de Casteljau", "    vec2 a = lerp(p0, p1, t);
    vec2 b = lerp(p1, p2, t);
    vec2 c = lerp(p2, p3, t);
    return lerp(lerp(a, b, t), lerp(b, c, t), 0.5);", Wrong(&["Not yet", "The first, t ="])),
    ("18-bezier", "Lab: de Casteljau", "    vec2 q[4] = vec2[4](p0, p1, p2, p3);
    for (int level = 3; level > 0; level--) {
        for (int i = 0; i < level; i++) {
            q[i] = lerp(q[i], q[i + 1], t);
        }
    }
    return q[0];", Right),
    // 19-bezier-surfaces: Lab: the patch by de Casteljau. The tensor product allows either
    // order (rows in u then v, or columns in v then u) and the Bernstein form.
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    vec3 q[4];
    for (int i = 0; i < 4; i++) {
        q[i] = de_casteljau(p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3], v);
    }
    return de_casteljau(q[0], q[1], q[2], q[3], u);", Wrong(&["Not yet", "surface points", "The first, (u, v) ="])),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    return mix(mix(p[0], p[3], u), mix(p[12], p[15], u), v);", Wrong(&["Not yet", "surface points", "The first, (u, v) ="])),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    return de_casteljau(p[0], p[1], p[2], p[3], u);", Wrong(&["Not yet", "surface points", "The first, (u, v) ="])),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    vec3 q0 = de_casteljau(p[0], p[1], p[2], p[3], u);
    vec3 q3 = de_casteljau(p[12], p[13], p[14], p[15], u);
    return mix(q0, q3, v);", Wrong(&["Not yet", "surface points", "The first, (u, v) ="])),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    vec3 q[4];
    for (int i = 0; i < 4; i++) {
        q[i] = de_casteljau(p[3 * i], p[3 * i + 1], p[3 * i + 2], p[3 * i + 3], u);
    }
    return de_casteljau(q[0], q[1], q[2], q[3], v);", Wrong(&["Not yet", "surface points", "The first, (u, v) ="])),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    vec3 q[4];
    for (int i = 0; i < 3; i++) {
        q[i] = de_casteljau(p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3], u);
    }
    return de_casteljau(q[0], q[1], q[2], q[3], v);", Wrong(&["Not yet", "surface points", "The first, (u, v) ="])),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    vec3 q[4];
    for (int i = 0; i < 4; i++) {
        q[i] = de_casteljau(p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3], u);
    }
    return de_casteljau(q[0], q[1], q[2], q[3], v);", Right),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    vec3 c[4];
    for (int j = 0; j < 4; j++) {
        c[j] = de_casteljau(p[j], p[4 + j], p[8 + j], p[12 + j], v);
    }
    return de_casteljau(c[0], c[1], c[2], c[3], u);", Right),
    ("19-bezier-surfaces", "Lab: the patch by de Casteljau", "    float bu[4] = float[4]((1.0 - u) * (1.0 - u) * (1.0 - u), 3.0 * u * (1.0 - u) * (1.0 - u),
                           3.0 * u * u * (1.0 - u), u * u * u);
    float bv[4] = float[4]((1.0 - v) * (1.0 - v) * (1.0 - v), 3.0 * v * (1.0 - v) * (1.0 - v),
                           3.0 * v * v * (1.0 - v), v * v * v);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
            sum += bv[i] * bu[j] * p[4 * i + j];
        }
    }
    return sum;", Right),
    // 24-shader-programs: Lab: the texture as k_d's colour.
    ("24-shader-programs", "Lab: the texture as k_d's colour", "    vec3 c = texture(tex, v_uv.yx).rgb;", Wrong(&["Not yet", "your `c`", "between texels"])),
    ("24-shader-programs", "Lab: the texture as k_d's colour", "    vec3 c = texture(tex, vec2(v_uv.x, 1.0 - v_uv.y)).rgb;", Wrong(&["Not yet", "your `c`", "between texels"])),
    ("24-shader-programs", "Lab: the texture as k_d's colour", "    vec3 c = v_color * texture(tex, v_uv).rgb;", Wrong(&["Not yet", "your `c`", "between texels"])),
    ("24-shader-programs", "Lab: the texture as k_d's colour", "    ivec2 size = textureSize(tex, 0);
    ivec2 nearest = clamp(ivec2(v_uv * vec2(size)), ivec2(0), size - 1);
    vec3 c = texelFetch(tex, nearest, 0).rgb;", Wrong(&["Not yet", "your `c`"])),
    ("24-shader-programs", "Lab: the texture as k_d's colour", "    vec3 c = texture(tex, v_uv).rgb / 255.0;", Wrong(&["Not yet", "your `c`", "between texels"])),
    ("24-shader-programs", "Lab: the texture as k_d's colour", "    vec4 texel = texture(tex, v_uv);
    vec3 c = texel.xyz;", Right),
    ("24-shader-programs", "Lab: the texture as k_d's colour", "vec3 surface(vec2 uv) {
    return texture(tex, uv).rgb;
}
---
    vec3 c = surface(v_uv);", Right),
    ("24-shader-programs", "Lab: the texture as k_d's colour", "    vec3 c = mix(v_color, texture(tex, v_uv).rgb, 1.0);", Right),
    // 24-shader-programs: Lab: the diffuse term.
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * light_color * max(dot(n, l), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * v_color * light_color * dot(n, l);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * v_color * light_color * max(dot(n, v), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L = kd * v_color * light_color * max(dot(n, l), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    L += kd * v_color * max(dot(n, h), 0.0);", Wrong(&["Not yet", "`color`"])),
    ("24-shader-programs", "Lab: the diffuse term", "    float lambert = clamp(dot(l, n), 0.0, 1.0);
    L = L + lambert * light_color * v_color * kd;", Right),
    ("24-shader-programs", "Lab: the diffuse term", "    L += mix(vec3(0.0), kd * v_color * light_color, max(dot(n, l), 0.0));", Right),
    ("24-shader-programs", "Lab: the diffuse term", "    float d = dot(n, l);
    if (d > 0.0) {
        L += kd * v_color * light_color * d;
    }", Right),
    // 24-shader-programs: Lab: Gouraud shading in the vertex shader.
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "    vec3 l = normalize(light_pos - p);
    vec3 r = reflect(-l, n);
    lit += kd * c * light_color * max(dot(n, l), 0.0);
    if (dot(n, l) > 0.0) {
        specular += ks * light_color * pow(max(dot(r, v), 0.0), shininess);
    }", Wrong(&["Not yet", "your vertex shader's `specular`"])),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "    vec3 l = normalize(light_pos - p);
    vec3 h = normalize(l + v);
    lit += kd * c * light_color * dot(n, l);
    if (dot(n, l) > 0.0) {
        specular += ks * light_color * pow(max(dot(n, h), 0.0), shininess);
    }", Wrong(&["Not yet", "your vertex shader's `lit`"])),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "    vec3 l = normalize(p - light_pos);
    vec3 h = normalize(l + v);
    lit += kd * c * light_color * max(dot(n, l), 0.0);
    if (dot(n, l) > 0.0) {
        specular += ks * light_color * pow(max(dot(n, h), 0.0), shininess);
    }", Wrong(&["Not yet", "your vertex shader's `l`"])),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "    vec3 l = normalize(light_pos - p);
    vec3 h = l + v;
    lit += kd * c * light_color * max(dot(n, l), 0.0);
    if (dot(n, l) > 0.0) {
        specular += ks * light_color * pow(max(dot(n, h), 0.0), shininess);
    }", Wrong(&["Not yet", "your vertex shader's `h`", "is it normalized?"])),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "    vec3 l = normalize(light_pos - p);
    vec3 h = normalize(l + v);
    lit = kd * c * light_color * max(dot(n, l), 0.0);
    if (dot(n, l) > 0.0) {
        specular += ks * light_color * pow(max(dot(n, h), 0.0), shininess);
    }", Wrong(&["Not yet", "your vertex shader's `lit`"])),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "    vec3 l = normalize(light_pos - p);
    vec3 h = normalize(l + v);
    lit += kd * c * light_color * max(dot(n, l), 0.0);
    if (dot(n, l) > 0.0) {
        specular += ks * c * light_color * pow(max(dot(n, h), 0.0), shininess);
    }", Wrong(&["Not yet", "your vertex shader's `specular`"])),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "float blinn_phong(vec3 n, vec3 l, vec3 v, float p) {
    float d = max(dot(n, l), 0.0);
    return d > 0.0 ? pow(max(dot(n, normalize(l + v)), 0.0), p) : 0.0;
}
---
    vec3 to_light = normalize(light_pos - p);
    lit += kd * c * light_color * max(dot(n, to_light), 0.0);
    specular += ks * light_color * blinn_phong(n, to_light, v, shininess);", Right),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "uniform Light lights[MAX_LIGHTS];
uniform int light_count;
---
    for (int i = 0; i < light_count; i++) {
        if (lights[i].kind == LIGHT_POINT) {
            vec3 l = normalize(lights[i].position - p);
            float d = dot(n, l);
            lit += kd * c * lights[i].intensity * max(d, 0.0);
            if (d > 0.0) {
                specular += ks * lights[i].intensity * pow(max(dot(n, normalize(l + v)), 0.0), shininess);
            }
        }
    }", Right),
    ("24-shader-programs", "Lab: Gouraud shading in the vertex shader", "    vec3 l = normalize(light_pos - p);
    float nl = clamp(dot(l, n), 0.0, 1.0);
    lit = lit + nl * kd * c * light_color;
    specular += nl > 0.0 ? ks * light_color * pow(max(dot(n, normalize(v + l)), 0.0), shininess) : vec3(0.0);", Right),
];
