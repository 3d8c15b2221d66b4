#pragma once
// Lesson 01 exercises. Write them in exercises.cpp; grade with
//   make grade LESSON=01   (it builds what changed first)
// and see yours live with  lesson_01_lighting --set impl=student
// (the lesson then shades every vertex on the CPU with YOUR functions).
#include <glm/glm.hpp>
#include "grading/stub.hpp"  // SHADOWLAB_STUB: the marker in every untouched stub

namespace shadowlab::ex01 {

// EXERCISE 01.1: the lighting term of one light, with its visibility V_i ([Tarantsev-L12], illumination
// with visibility):   V f_att I [kd (N.L) + ks (R.V)^shininess]
// N, L, V are unit vectors: the surface normal, the direction TO the light, the direction TO the
// eye. R is L mirrored about N (glm::reflect(-L, N)). Clamp R.V at 0. A surface facing away from
// the light (N.L <= 0) receives nothing: return black (no highlight behind the terminator).
// lightColor is I (colour times intensity), kd the diffuse colour, ks the specular weight.
glm::vec3 lightContribution(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V, const glm::vec3& lightColor,
                            float fatt, float visibility, const glm::vec3& kd, float ks, float shininess);

// EXERCISE 01.2: the matrix that maps normalised device coordinates [-1,1]^3 onto texture space
// [0,1]^3: translate(0.5) * scale(0.5) ([Boreskov2005], the texture matrix). Every shadow-map lookup
// ends with it. Remember GLM matrices are column-major: m[column][row].
glm::mat4 ndcToTexture();

// EXERCISE 01.3: the attenuation factor f_att = 1 / (c0 + c1 d + c2 d^2) ([Tarantsev-L12]), with
// c = (c0, c1, c2) and d the distance to the light.
float attenuation(const glm::vec3& c, float d);

// EXERCISE 01.4: a spot light's cone: 1 inside the inner half-angle, 0 outside the outer one, and
// a smoothstep in between on the cosines: t = clamp((cosAngle - cos(outer)) / (cos(inner) -
// cos(outer)), 0, 1), factor = t^2 (3 - 2t). cosAngle = dot(spot axis, -L). Angles in radians.
float spotFactor(float cosAngle, float innerHalfAngle, float outerHalfAngle);

}  // namespace shadowlab::ex01
