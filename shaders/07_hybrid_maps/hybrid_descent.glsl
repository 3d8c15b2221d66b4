// The hybrid map's lookup, shared by its visibility (shadow_hybrid.frag) and its views: from the
// root word over a source texel down the index to the finest stored depth. Mirrors
// common/algorithms/hybrid_map (descend); keep the two in step. The words, records and
// HybridTexel are in hybrid_texel.glsl.
#include "07_hybrid_maps/hybrid_texel.glsl"

// The descent, hybridDescend(root, records, levels, s): exercise 07.5 (GLSL). The student's with
// impl=student in lesson 07 (the technique's shaderDefines() add SHADOWLAB_STUDENT_DESCENT when the
// lesson sets student.glslDescent), else the reference (withheld from the student handout).
#ifdef SHADOWLAB_STUDENT_DESCENT
#include "07_hybrid_maps/exercises.glsl"
#else
#include "07_hybrid_maps/exercises_reference.glsl"
#endif
