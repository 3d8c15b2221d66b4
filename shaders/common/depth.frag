#version 410 core
// The depth pass, fragment: no colour is written, only depth. An alpha-tested caster (leaf cards, a
// fence) must discard its holes HERE too, or it casts the shadow of a solid card ([Boreskov2005]).
in vec2 vUv;

uniform bool uAlphaTest;      // the lesson's switch: off shows the solid-card shadows
uniform bool uAlphaLevel0;    // test the texture's full-resolution alpha, not the mip level the map's texel picks
uniform float uAlphaCutoff;   // the material's cutoff; 0 for opaque materials
uniform bool uUseTexture;
uniform sampler2D uTexture;

void main() {
  if (!uAlphaTest || !uUseTexture || uAlphaCutoff <= 0.0) return;
  float alpha = uAlphaLevel0 ? textureLod(uTexture, vUv, 0.0).a : texture(uTexture, vUv).a;
  if (alpha < uAlphaCutoff) discard;
}
