// Lesson 01: YOUR implementations. Each stub compiles and returns a neutral value; replace the
// body, then grade with  make grade LESSON=01   (it builds what changed first)
#include "exercises.hpp"

namespace shadowlab::ex01 {

// EXERCISE 01.1
glm::vec3 lightContribution(const glm::vec3& N, const glm::vec3& L, const glm::vec3& V, const glm::vec3& lightColor,
                            float fatt, float visibility, const glm::vec3& kd, float ks, float shininess) {
  SHADOWLAB_STUB("01.1");  // delete this line when you write the exercise
  // TODO: V f_att I [kd (N.L) + ks (R.V)^shininess]
  return glm::vec3(0.0f);
}

// EXERCISE 01.2
glm::mat4 ndcToTexture() {
  SHADOWLAB_STUB("01.2");  // delete this line when you write the exercise
  // TODO: translate(0.5) * scale(0.5)
  return glm::mat4(1.0f);
}

// EXERCISE 01.3
float attenuation(const glm::vec3& c, float d) {
  SHADOWLAB_STUB("01.3");  // delete this line when you write the exercise
  // TODO: 1 / (c0 + c1 d + c2 d^2)
  return 1.0f;
}

// EXERCISE 01.4
float spotFactor(float cosAngle, float innerHalfAngle, float outerHalfAngle) {
  SHADOWLAB_STUB("01.4");  // delete this line when you write the exercise
  // TODO: smoothstep between the outer and the inner cone
  return 1.0f;
}

}  // namespace shadowlab::ex01
