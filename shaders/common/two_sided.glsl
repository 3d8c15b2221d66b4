// Whether the surface being shaded is a two-sided card (a leaf, a sheet of paper): scene.frag
// turns its normal toward the viewer, and the soft shadows' lookups take the cards' own bias
// (soft_maps.glsl). Its own file, included by both: a program's fragment files, compiled as one
// source in WebGL2, may declare a uniform only once.
uniform bool uTwoSided;
