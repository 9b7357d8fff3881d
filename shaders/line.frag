#version 330 core
in float v_side;
in vec4 v_color;
out vec4 frag;
void main() {
    float d = abs(v_side);
    float aa = max(fwidth(v_side), 1e-4);
    frag = vec4(v_color.rgb, v_color.a * (1.0 - smoothstep(1.0 - 1.5 * aa, 1.0, d)));
}
