#version 330 core
// A perfect mirror (environment mapping, no lighting): the cube map `environment` seen in the
// mirror direction of the view vector, r = reflect(−v, n) = 2(n·v)n − v. pipelens binds its
// room; the peer binds the six faces pipelens exported (cube0_+x.png …), each face's top row
// first, filtered bilinearly and clamped at its edges.
uniform vec3 eye;
uniform samplerCube environment;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 v = normalize(eye - w_pos);
    color = vec4(texture(environment, reflect(-v, n)).rgb, 1.0);
}
