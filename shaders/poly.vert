#version 330 core
// Filled convex polygons as a triangle fan from each body's centre; a_edge is the
// distance (metres) to the polygon's outline, interpolated linearly across each triangle.
layout(location = 0) in vec2 a_pos;
layout(location = 1) in float a_edge;
layout(location = 2) in vec4 a_fill;
layout(location = 3) in vec4 a_line;
uniform mat3 u_view;
out float v_edge;
out vec4 v_fill;
out vec4 v_line;
void main() {
    vec3 p = u_view * vec3(a_pos, 1.0);
    gl_Position = vec4(p.xy, 0.0, 1.0);
    v_edge = a_edge;
    v_fill = a_fill;
    v_line = a_line;
}
