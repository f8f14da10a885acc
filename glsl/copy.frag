// The benchmark's baseline: one fetch and one write per texel, the floor
// under any step pass on the same format and size.
uniform sampler2D uState;
uniform vec2 uInvSize;
out vec4 outState;

void main() {
    outState = texture(uState, gl_FragCoord.xy * uInvSize);
}
