// The casters' alpha test (depth.frag, depth_moments.frag): an alpha-tested card discards its holes
// in every depth pass too, or it casts the shadow of a solid card ([Boreskov2005]). CasterPass picks
// one build per caster (common/technique/casters): on a software renderer a test a uniform switches
// off is still paid, and a shader that can discard costs every opaque caster its early depth test.
//   OPAQUE_CASTER  no texture, no discard: the caster is opaque, or the lesson's switch is off
//   ALPHA_LEVEL0   the texture's full-resolution alpha, as the ground truth's rays test it, not the
//                  mip level a map texel's footprint picks
//   (neither)      the alpha of the mip level the footprint picks
in vec2 vUv;

uniform float uAlphaCutoff;  // the material's cutoff
uniform sampler2D uTexture;

void casterAlphaTest() {
#ifndef OPAQUE_CASTER
#ifdef ALPHA_LEVEL0
  float alpha = textureLod(uTexture, vUv, 0.0).a;
#else
  float alpha = texture(uTexture, vUv).a;
#endif
  if (alpha < uAlphaCutoff) discard;
#endif
}
