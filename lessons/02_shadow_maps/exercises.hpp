#pragma once
// Lesson 02 exercises. Write them in exercises.cpp; grade with
//   make grade LESSON=02   (it builds what changed first)
// and see yours live with  lesson_02_shadow_maps --set impl=student --set compare=cpu_vertex
// (the texture matrix of the GPU lookup is yours, and every vertex's V comes from YOUR lookup on a
// read-back of the shadow map).
#include <glm/glm.hpp>

#include "algorithms/shadow_math.hpp"
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex02 {

// EXERCISE 02.1: the shadow texture matrix ([Boreskov2005]): world -> shadow-map space [0,1]^3,
//   T = translate(0.5) * scale(0.5) * P_light * V_light
// Applied to (p, 1) and divided by w it gives (u, v, depth) of p in the light's depth map.
glm::mat4 shadowTextureMatrix(const glm::mat4& lightProjection, const glm::mat4& lightView);

// EXERCISE 02.2: the depth comparison of ARB_shadow with GL_LEQUAL, with a bias: return 1 (lit)
// when the fragment's depth, moved toward the light by `bias`, is not farther than the depth the
// light saw there (fragmentDepth - bias <= storedDepth), else 0 (shadowed).
float depthCompare(float fragmentDepth, float storedDepth, float bias);

// EXERCISE 02.3: one shadow-map lookup on the CPU, the way the hardware does it with GL_NEAREST.
// uvz = (u, v, depth) in [0,1]^3. Read the texel (floor(u * width), floor(v * height)) with
// map.at(x, y) (row 0 is v = 0) and compare with your depthCompare. Outside the map (u or v outside
// [0,1]) or beyond the far plane (depth > 1) the light saw nothing: return 1 (lit).
float shadowLookup(const shadow::DepthMap& map, const glm::vec3& uvz, float bias);

}  // namespace shadowlab::ex02
