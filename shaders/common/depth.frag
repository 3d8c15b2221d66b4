#version 410 core
// The depth pass, fragment: no colour is written, only depth. An alpha-tested caster (leaf cards, a
// fence) must discard its holes HERE too, or it casts the shadow of a solid card ([Boreskov2005]).
in vec2 vUv;

uniform bool uAlphaTest;      // the lesson's switch: off shows the solid-card shadows
uniform float uAlphaCutoff;   // the material's cutoff; 0 for opaque materials
uniform bool uUseTexture;
uniform sampler2D uTexture;

void main() {
  if (uAlphaTest && uUseTexture && uAlphaCutoff > 0.0 && texture(uTexture, vUv).a < uAlphaCutoff) discard;
}
