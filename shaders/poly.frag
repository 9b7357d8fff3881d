#version 330 core
in float v_edge;
in vec4 v_fill;
in vec4 v_line;
uniform float u_scale;       // pixels per metre
uniform float u_outline;     // outline width in pixels
out vec4 frag;
void main() {
    float px = v_edge * u_scale;                 // pixels to the outline
    float aa = max(fwidth(px), 1e-4);
    float inner = smoothstep(u_outline - aa, u_outline + aa, px);
    vec4 c = mix(v_line, v_fill, inner);
    // soft inner shading towards the middle of the body
    c.rgb *= 0.92 + 0.08 * clamp(px / (6.0 * u_outline + 1.0), 0.0, 1.0);
    // anti-aliased outer edge
    c.a *= clamp(px / aa + 0.5, 0.0, 1.0);
    frag = c;
}
