#version 330 core
in vec2 v_local;
in float v_radius;
in float v_spoke;
in vec4 v_fill;
in vec4 v_line;
uniform float u_scale;
uniform float u_outline;
out vec4 frag;
void main() {
    float r = length(v_local);
    float rpx = v_radius * u_scale;            // radius in pixels
    float px = (1.0 - r) * rpx;                // pixels to the rim
    if (px < -1.0) discard;
    float inner = smoothstep(u_outline - 0.75, u_outline + 0.75, px);
    vec4 c = mix(v_line, v_fill, inner);
    if (v_spoke > 0.5) {
        float d = abs(v_local.y) * rpx;
        float s = (1.0 - smoothstep(0.5 * u_outline - 0.5, 0.5 * u_outline + 0.5, d)) * step(0.0, v_local.x);
        c = mix(c, v_line, s);
        c.rgb *= 0.92 + 0.08 * clamp(px / (6.0 * u_outline + 1.0), 0.0, 1.0);
    }
    c.a *= clamp(px + 0.5, 0.0, 1.0);
    frag = c;
}
