#version 330 core
// Matrix work in a fragment shader: a rotation built from an angle, its transpose as its
// inverse, a matrix inverted, a determinant, an outer product, a matrix times a matrix and a
// row vector times a matrix (v·M = Mᵀ·v).
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

mat3 rotate_y(float a) {
    float c = cos(a);
    float s = sin(a);
    return mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c);
}

void main() {
    vec3 n = normalize(w_nrm);
    mat3 r = rotate_y(0.8);
    vec3 turned = r * n;
    vec3 back = transpose(r) * turned;
    mat3 shear = mat3(1.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.25, 1.0);
    vec3 undone = inverse(shear) * (shear * back);
    float det = determinant(shear * r);
    mat3 o = outerProduct(turned, vec3(0.2, 0.3, 0.5));
    vec3 row = vec3(1.0, 0.5, 0.25) * mat3(o);
    mat2 m2 = mat2(turned.xy, turned.yz) * mat2(0.5, 0.1, -0.2, 0.7);
    float d = max(dot(undone, normalize(light_pos - w_pos)), 0.0);
    vec3 c = 0.5 + 0.5 * vec3(turned.x, m2[1][0], row.z);
    color = vec4(c * (0.3 + 0.7 * d) * det, 1.0);
}
