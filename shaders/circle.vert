#version 330 core
// Discs drawn as quads: a_local spans [-k, k] in the disc's rotated frame (x = body angle).
layout(location = 0) in vec2 a_pos;
layout(location = 1) in vec2 a_local;
layout(location = 2) in float a_radius;   // metres
layout(location = 3) in float a_spoke;    // 1: draw the radius line that shows rotation
layout(location = 4) in vec4 a_fill;
layout(location = 5) in vec4 a_line;
uniform mat3 u_view;
out vec2 v_local;
out float v_radius;
out float v_spoke;
out vec4 v_fill;
out vec4 v_line;
void main() {
    vec3 p = u_view * vec3(a_pos, 1.0);
    gl_Position = vec4(p.xy, 0.0, 1.0);
    v_local = a_local;
    v_radius = a_radius;
    v_spoke = a_spoke;
    v_fill = a_fill;
    v_line = a_line;
}
