#version 330 core
// Thick anti-aliased lines, expanded to quads on the CPU; a_side runs -1..1 across the line.
layout(location = 0) in vec2 a_pos;
layout(location = 1) in float a_side;
layout(location = 2) in vec4 a_color;
uniform mat3 u_view;
out float v_side;
out vec4 v_color;
void main() {
    vec3 p = u_view * vec3(a_pos, 1.0);
    gl_Position = vec4(p.xy, 0.0, 1.0);
    v_side = a_side;
    v_color = a_color;
}
