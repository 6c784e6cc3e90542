#version 330 core
// Red: the smooth value; green: the noperspective one; blue: the flat one. Where a triangle is
// seen at a slant, red and green part ways (lesson 12); blue is constant on each triangle.
in vec3 v_smooth;
noperspective in vec3 v_affine;
flat in vec3 v_flat;

out vec4 color;

void main() {
    color = vec4(v_smooth.x, v_affine.x, v_flat.x, 1.0);
}
