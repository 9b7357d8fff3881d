#version 330 core
// Plain coloured geometry (the background grid, drawn as GL_LINES).
layout(location = 0) in vec2 a_pos;
layout(location = 1) in vec4 a_color;
uniform mat3 u_view;
out vec4 v_color;
void main() {
    vec3 p = u_view * vec3(a_pos, 1.0);
    gl_Position = vec4(p.xy, 0.0, 1.0);
    v_color = a_color;
}
