#include "algorithms/lighting.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab::lighting {

float attenuation(const glm::vec3& c, float d) {
  const float denom = c.x + c.y * d + c.z * d * d;
  if (!(denom > 0.0f))
    throw std::invalid_argument("attenuation: c0 + c1 d + c2 d^2 = " + std::to_string(denom) +
                                " at d = " + std::to_string(d) + " (must be > 0)");
  return 1.0f / denom;
}

float spotFactor(float cosAngle, float inner, float outer) {
  const float cosInner = std::cos(inner), cosOuter = std::cos(outer);
  if (cosInner <= cosOuter) return cosAngle >= cosOuter ? 1.0f : 0.0f;
  const float t = std::clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec3 lightContribution(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V, const glm::vec3& lightColor,
                            float fatt, float visibility, const glm::vec3& kd, float ks, float shininess) {
  const float NdotL = glm::dot(N, L);
  if (NdotL <= 0.0f) return glm::vec3(0.0f);
  const glm::vec3 R = glm::reflect(-L, N);
  const float RdotV = std::max(glm::dot(R, V), 0.0f);
  return visibility * fatt * lightColor * (kd * NdotL + glm::vec3(ks * std::pow(RdotV, shininess)));
}

glm::vec3 lightContributionBlinn(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V,
                                 const glm::vec3& lightColor, float fatt, float visibility, const glm::vec3& kd,
                                 float ks, float shininess) {
  const float NdotL = glm::dot(N, L);
  if (NdotL <= 0.0f) return glm::vec3(0.0f);
  const glm::vec3 H = glm::normalize(L + V);
  const float NdotH = std::max(glm::dot(N, H), 0.0f);
  return visibility * fatt * lightColor * (kd * NdotL + glm::vec3(ks * std::pow(NdotH, shininess)));
}

glm::mat4 ndcToTexture() {
  return glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
}

glm::vec3 incidentRadiance(const Light& light, const glm::vec3& p) {
  if (!light.enabled) return glm::vec3(0.0f);
  glm::vec3 radiance = light.color * light.intensity;
  if (light.kind == LightKind::Directional) return radiance;
  radiance *= attenuation(light.attenuation, light.distanceTo(p));
  if (light.kind == LightKind::Spot)
    radiance *=
        spotFactor(glm::dot(glm::normalize(light.direction), -light.toLight(p)), light.spotInner, light.spotOuter);
  return radiance;
}

}  // namespace shadowlab::lighting
