#pragma once
// The trust boundary of grading: the student's code answers, a process without it judges.
//
// A grader calls the student's exercise functions through Graded proxies (tests/grading/calls/).
// In the student's process (--answers-record=FILE) every call runs the student's function and its
// answer (the returned value's bytes, or the exception it threw, and the stub markers it reached) is
// kept; the file is written when the run ends. The instructor's process (the reference grader, no
// student code in it; --answers-replay=FILE) runs the very same cases, and each call to an exercise
// function returns the recorded answer instead of computing one: every check, every expected value
// and every result file is decided there. So whatever the student's code does to files, memory or
// the grader's own state, it can only change its own answers. Without either flag (ctest -L exNN,
// the lesson's exercises panel) a proxy calls the function directly.
//
// Replay follows the calls in order and checks each one's name: the cases are deterministic for a
// seed, so the two processes call the same functions with the same arguments in the same order.
// An answer missing (the student's program ended early) or out of order fails the case that asked.
#include <cstdint>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "grading/stub.hpp"

namespace shadowlab::grading {

enum class AnswerMode { kDirect, kRecord, kReplay };
AnswerMode answerMode();
// Record: answers go to `path` when writeRecordedAnswers() runs (the grader's main, at its end).
void recordAnswersTo(const std::string& path);
bool writeRecordedAnswers(std::string& error);
// Replay: the answers of `path`; false (and why) when it cannot be read.
bool replayAnswersFrom(const std::string& path, std::string& error);
void useDirectAnswers();  // back to calling the functions (tests of this module)

// ---- the bytes of an answer ------------------------------------------------------------------------
// Values of trivially copyable types (numbers, glm vectors and matrices, small structs) as their
// bytes, std::vector element by element; other types provide encodeAnswer/decodeAnswer overloads
// found by argument-dependent lookup or declared before use (the calls headers).
class AnswerReader {
 public:
  explicit AnswerReader(const std::string& bytes) : bytes_(bytes) {}
  void read(void* out, std::size_t n) {
    if (n > bytes_.size() - at_) throw std::runtime_error("the recorded answer is shorter than its type");
    std::memcpy(out, bytes_.data() + at_, n);
    at_ += n;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

template <class T>
requires std::is_trivially_copyable_v<T>
void encodeAnswer(std::string& out, const T& v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }
template <class T>
requires std::is_trivially_copyable_v<T>
void decodeAnswer(AnswerReader& in, T& v) { in.read(&v, sizeof v); }
template <class T>
void encodeAnswer(std::string& out, const std::vector<T>& v) {
  encodeAnswer(out, std::uint64_t(v.size()));
  for (const T& e : v) encodeAnswer(out, e);
}
template <class T>
void decodeAnswer(AnswerReader& in, std::vector<T>& v) {
  std::uint64_t n = 0;
  decodeAnswer(in, n);
  if (n > (std::uint64_t(1) << 32)) throw std::runtime_error("the recorded answer holds an impossible vector size");
  v.resize(std::size_t(n));
  for (T& e : v) decodeAnswer(in, e);
}

// ---- one call ---------------------------------------------------------------------------------------
struct Answer {
  std::string call;                // "ex01::attenuation"
  std::vector<std::string> stubs;  // the SHADOWLAB_STUB markers the call reached
  int thrown = 0;                  // 0: returned; else which exception (see answers.cpp)
  std::string what;                // the exception's message
  std::string value;               // the returned value's bytes
};
void recordAnswer(Answer answer);
// The file's bytes: a magic line, then each answer's fields, sizes first. parseAnswers refuses
// anything else (the student's process wrote it: never trusted) with why, in `error`.
std::string serializeAnswers(const std::vector<Answer>& answers);
bool parseAnswers(const std::string& bytes, std::vector<Answer>& answers, std::string& error);
// The next recorded answer, which must be for `call`; throws std::runtime_error (naming the call and
// why) when there is none or the order differs. Its stub markers are reached again here.
Answer nextAnswer(const char* call);
// Records that `call` threw (the exception in flight) and rethrows it.
[[noreturn]] void recordThrownAndRethrow(const char* call, const std::set<std::string>& stubsBefore);
// Throws the exception an answer recorded (the same standard type, the same message).
[[noreturn]] void rethrowRecorded(const Answer& answer);
std::vector<std::string> stubsSince(const std::set<std::string>& before);

// A proxy with exactly F's parameters (so braced arguments work), named after the function.
template <auto F, class Signature>
struct Graded;
template <auto F, class R, class... A>
struct Graded<F, R (*)(A...)> {
  const char* call;
  R operator()(A... args) const {
    const AnswerMode mode = answerMode();
    if (mode == AnswerMode::kDirect) return F(std::forward<A>(args)...);
    if (mode == AnswerMode::kRecord) {
      const std::set<std::string> before = stubsReached();
      try {
        R result = F(std::forward<A>(args)...);
        Answer a{call, stubsSince(before), 0, "", ""};
        encodeAnswer(a.value, result);
        recordAnswer(std::move(a));
        return result;
      } catch (...) { recordThrownAndRethrow(call, before); }
    }
    const Answer a = nextAnswer(call);
    if (a.thrown != 0) rethrowRecorded(a);
    R result{};
    AnswerReader in(a.value);
    decodeAnswer(in, result);
    if (!in.done())
      throw std::runtime_error(std::string("the recorded answer of ") + call + " is longer than its type");
    return result;
  }
};

}  // namespace shadowlab::grading

// In a calls header, inside namespace shadowlab::exNN_graded: the proxy for shadowlab::exNN::fn.
#define SHADOWLAB_GRADED_CALL(ns, fn)                                                                        \
  inline constexpr ::shadowlab::grading::Graded<&::shadowlab::ns::fn, decltype(&::shadowlab::ns::fn)> fn{#ns \
                                                                                                         ":" \
                                                                                                         ":" #fn};
