#pragma once
// The lecture's illumination model with the visibility term ([Tarantsev-L12], "illumination with
// visibility"):
//   I = ka Ia + sum_i V_i f_att,i I_i [kd (N.L_i) + ks (R_i.V)^pow]
// V_i in {0,1} (or [0,1] for soft shadows) is what the rest of the course computes. These are the
// reference implementations; shaders/common/lighting.glsl mirrors them for the GPU, and lesson 01's
// exercises ask students to write them.
#include <vector>

#include <glm/glm.hpp>

#include "core/light.hpp"

namespace shadowlab::lighting {

// f_att = 1 / (c0 + c1 d + c2 d^2). Coefficients must keep the denominator positive for d >= 0.
float attenuation(const glm::vec3& c, float d);

// Smooth cone fall-off of a spot light: 1 inside the inner half-angle, 0 outside the outer one,
// smoothstep between (in cosines). `cosAngle` = dot(spot axis, -L).
float spotFactor(float cosAngle, float innerHalfAngle, float outerHalfAngle);

// One light's term: V f_att I [kd (N.L) + ks (R.V)^pow], R = reflect(-L, N). N, L, V are unit
// vectors (L toward the light, V toward the eye). Back-facing (N.L <= 0) gives 0: no diffuse and no
// specular highlight leaking around the terminator.
glm::vec3 lightContribution(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V, const glm::vec3& lightColor,
                            float fatt, float visibility, const glm::vec3& kd, float ks, float shininess);

// Blinn's variant, (N.H)^pow with H = normalize(L + V): what real-time code usually uses.
glm::vec3 lightContributionBlinn(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V,
                                 const glm::vec3& lightColor, float fatt, float visibility, const glm::vec3& kd,
                                 float ks, float shininess);

// translate(0.5) * scale(0.5): maps [-1,1]^3 (NDC) onto [0,1]^3 (texture coordinates and depth),
// the last step of every shadow-map lookup ([Boreskov2005]).
glm::mat4 ndcToTexture();

// f_att, spot cone and colour of `light` at point p (everything but V and the material).
glm::vec3 incidentRadiance(const Light& light, const glm::vec3& p);

}  // namespace shadowlab::lighting
