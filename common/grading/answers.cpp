#include "grading/answers.hpp"

#include <algorithm>
#include <exception>
#include <fstream>
#include <iterator>
#include <mutex>
#include <new>
#include <sstream>

namespace shadowlab::grading {
namespace {

constexpr char kMagic[] = "shadowlab answers 1\n";

// The exceptions a recorded answer can stand for: the standard ones by type, anything else as
// std::runtime_error with what we know.
enum Thrown : int {
  kNone = 0,
  kInvalidArgument,
  kOutOfRange,
  kDomainError,
  kLengthError,
  kLogicError,
  kOverflowError,
  kRangeError,
  kRuntimeError,
  kBadAlloc,
  kOtherStd,
  kNotStd
};

struct State {
  std::mutex mutex;
  AnswerMode mode = AnswerMode::kDirect;
  std::string path;
  std::vector<Answer> answers;
  std::size_t next = 0;
};
State& state() {
  static State s;
  return s;
}

void putString(std::string& out, const std::string& s) {
  encodeAnswer(out, std::uint64_t(s.size()));
  out += s;
}
// A length field is the file's word, not the truth: never allocate more than the bytes that are
// left (a damaged length of 2 GiB must fail as "truncated", not take the memory first).
std::string getString(std::istream& in, std::uint64_t total) {
  std::uint64_t n = 0;
  if (!in.read(reinterpret_cast<char*>(&n), sizeof n)) throw std::runtime_error("truncated or damaged");
  const std::streamoff at = in.tellg();
  if (at < 0 || n > total - std::uint64_t(at)) throw std::runtime_error("truncated");
  std::string s(std::size_t(n), '\0');
  if (n > 0 && !in.read(s.data(), std::streamsize(n))) throw std::runtime_error("truncated");
  return s;
}

}  // namespace

AnswerMode answerMode() {
  std::lock_guard<std::mutex> lock(state().mutex);
  return state().mode;
}

void recordAnswersTo(const std::string& path) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().mode = AnswerMode::kRecord;
  state().path = path;
  state().answers.clear();
}

void useDirectAnswers() {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().mode = AnswerMode::kDirect;
  state().answers.clear();
  state().next = 0;
}

std::string serializeAnswers(const std::vector<Answer>& answers) {
  std::string bytes = kMagic;
  for (const Answer& a : answers) {
    putString(bytes, a.call);
    encodeAnswer(bytes, std::uint64_t(a.stubs.size()));
    for (const std::string& s : a.stubs) putString(bytes, s);
    encodeAnswer(bytes, std::int32_t(a.thrown));
    putString(bytes, a.what);
    putString(bytes, a.value);
  }
  return bytes;
}

bool parseAnswers(const std::string& bytes, std::vector<Answer>& answers, std::string& error) {
  answers.clear();
  std::istringstream in(bytes);
  const std::uint64_t total = bytes.size();
  std::string magic(sizeof kMagic - 1, '\0');
  if (!in.read(magic.data(), std::streamsize(magic.size())) || magic != kMagic) {
    error = "not an answers file";
    return false;
  }
  try {
    while (in.peek() != std::char_traits<char>::eof()) {
      Answer a;
      a.call = getString(in, total);
      std::uint64_t stubs = 0;
      if (!in.read(reinterpret_cast<char*>(&stubs), sizeof stubs) || stubs > 64) throw std::runtime_error("damaged");
      for (std::uint64_t k = 0; k < stubs; ++k) a.stubs.push_back(getString(in, total));
      std::int32_t thrown = 0;
      if (!in.read(reinterpret_cast<char*>(&thrown), sizeof thrown)) throw std::runtime_error("truncated");
      a.thrown = thrown;
      a.what = getString(in, total);
      a.value = getString(in, total);
      answers.push_back(std::move(a));
    }
  } catch (const std::exception& e) {
    error = "answer " + std::to_string(answers.size() + 1) + " is " + e.what();
    return false;
  }
  return true;
}

bool writeRecordedAnswers(std::string& error) {
  std::lock_guard<std::mutex> lock(state().mutex);
  if (state().mode != AnswerMode::kRecord) return true;
  const std::string bytes = serializeAnswers(state().answers);
  std::ofstream out(state().path, std::ios::binary | std::ios::trunc);
  if (!out.write(bytes.data(), std::streamsize(bytes.size())) || !out.flush()) {
    error = "cannot write the answers to " + state().path;
    return false;
  }
  return true;
}

bool replayAnswersFrom(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "no answers file " + path;
    return false;
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Answer> answers;
  if (!parseAnswers(bytes, answers, error)) {
    error = path + (error == "not an answers file" ? " is " : ": ") + error;
    return false;
  }
  std::lock_guard<std::mutex> lock(state().mutex);
  state().mode = AnswerMode::kReplay;
  state().answers = std::move(answers);
  state().next = 0;
  return true;
}
void recordAnswer(Answer answer) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().answers.push_back(std::move(answer));
}

Answer nextAnswer(const char* call) {
  Answer a;
  {
    std::lock_guard<std::mutex> lock(state().mutex);
    State& s = state();
    if (s.next >= s.answers.size())
      throw std::runtime_error(std::string("no answer from your code for this call of ") + call +
                               ": your program ended before the grader's cases did (exit() or abort() in "
                               "your code, or a crash after the last answer?)");
    if (s.answers[s.next].call != call)
      throw std::runtime_error(std::string("the answers do not follow the grader's calls: expected one of ") + call +
                               ", found one of " + s.answers[s.next].call +
                               " (does your code change what the grader computes between calls?)");
    a = s.answers[s.next++];
  }
  for (const std::string& stub : a.stubs) stubReached(stub.c_str());
  return a;
}

std::vector<std::string> stubsSince(const std::set<std::string>& before) {
  std::vector<std::string> added;
  const std::set<std::string> now = stubsReached();
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(added));
  return added;
}

void recordThrownAndRethrow(const char* call, const std::set<std::string>& stubsBefore) {
  Answer a{call, stubsSince(stubsBefore), kNotStd, "an exception that is not a std::exception", ""};
  try {
    throw;
  } catch (const std::invalid_argument& e) {
    a.thrown = kInvalidArgument, a.what = e.what();
  } catch (const std::out_of_range& e) {
    a.thrown = kOutOfRange, a.what = e.what();
  } catch (const std::domain_error& e) {
    a.thrown = kDomainError, a.what = e.what();
  } catch (const std::length_error& e) {
    a.thrown = kLengthError, a.what = e.what();
  } catch (const std::logic_error& e) {
    a.thrown = kLogicError, a.what = e.what();
  } catch (const std::overflow_error& e) {
    a.thrown = kOverflowError, a.what = e.what();
  } catch (const std::range_error& e) {
    a.thrown = kRangeError, a.what = e.what();
  } catch (const std::runtime_error& e) {
    a.thrown = kRuntimeError, a.what = e.what();
  } catch (const std::bad_alloc& e) { a.thrown = kBadAlloc, a.what = e.what(); } catch (const std::exception& e) {
    a.thrown = kOtherStd, a.what = e.what();
  } catch (...) {}
  recordAnswer(std::move(a));
  throw;
}

void rethrowRecorded(const Answer& a) {
  const std::string& w = a.what;
  switch (a.thrown) {
    case kInvalidArgument: throw std::invalid_argument(w);
    case kOutOfRange: throw std::out_of_range(w);
    case kDomainError: throw std::domain_error(w);
    case kLengthError: throw std::length_error(w);
    case kLogicError: throw std::logic_error(w);
    case kOverflowError: throw std::overflow_error(w);
    case kRangeError: throw std::range_error(w);
    case kBadAlloc: throw std::bad_alloc();
    default: throw std::runtime_error(w);
  }
}

}  // namespace shadowlab::grading
