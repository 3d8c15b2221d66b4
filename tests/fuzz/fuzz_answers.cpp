// The answers file of a graded run (grading/answers): written by the student's process, so never
// trusted. Any bytes: refused with a reason, or parsed into answers that serialise back to the
// very same bytes (nothing read past, nothing invented).
#include "fuzz_support.hpp"
#include "grading/answers.hpp"

using namespace shadowlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::vector<grading::Answer> answers;
  std::string error;
  if (!grading::parseAnswers(bytes, answers, error)) {
    FUZZ_CHECK(!error.empty());
    return 0;
  }
  FUZZ_CHECK(grading::serializeAnswers(answers) == bytes);
  return 0;
}
