#pragma once
// The marker in every untouched exercise stub:
//
//   float attenuation(const glm::vec3& c, float d) {
//     SHADOWLAB_STUB("01.3");  // delete this line when you write the exercise
//     return 1.0f;
//   }
//
// It records that the stub ran, so the lesson's exercises panel can say "stub" rather than
// "failing" and, with impl=student, the banner can say which stub is behind a black or wrong
// picture. It changes no result: graders score what the function returns, and an untouched stub
// scores 0 because every case fails on it (validity.exNN.stubs proves that).
// GLSL exercises carry the same word in a comment (`// SHADOWLAB_STUB`), read from the file.
#include <set>
#include <string>

namespace shadowlab::grading {

void stubReached(const char* exercise);
// The exercises whose stub ran since the last clearStubsReached(), e.g. {"01.1", "01.3"}.
std::set<std::string> stubsReached();
void clearStubsReached();

}  // namespace shadowlab::grading

#define SHADOWLAB_STUB(exercise) ::shadowlab::grading::stubReached(exercise)
