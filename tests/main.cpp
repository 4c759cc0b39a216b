// The suites' main: doctest's, and the run-time skips of tests/skip.hpp, which doctest 2.4
// does not have. A listener follows the test cases as they run, so skip() knows whose it is.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "skip.hpp"

namespace {

struct Skipped {
  std::string test_case, why;
};

struct SkipLedger {
  std::string running, why;      // the test case running now, and why it skipped (empty: it did not)
  std::vector<Skipped> skipped;  // test cases that ended skipped without failing
  unsigned test_cases_run = 0;
};

SkipLedger& ledger() {
  static SkipLedger l;
  return l;
}

struct SkipListener : doctest::IReporter {
  explicit SkipListener(const doctest::ContextOptions&) {}
  void test_case_start(const doctest::TestCaseData& t) override {
    ledger().running = t.m_name;
    ledger().why.clear();
  }
  void test_case_end(const doctest::CurrentTestCaseStats& s) override {
    if (!ledger().why.empty() && s.testCaseSuccess) ledger().skipped.push_back({ledger().running, ledger().why});
    ledger().running.clear();
  }
  void test_run_end(const doctest::TestRunStats& s) override { ledger().test_cases_run = s.numTestCasesPassingFilters; }
  void report_query(const doctest::QueryData&) override {}
  void test_run_start() override {}
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_exception(const doctest::TestCaseException&) override {}
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData&) override {}
  void log_message(const doctest::MessageData&) override {}
  void test_case_skipped(const doctest::TestCaseData&) override {}
};
REGISTER_LISTENER("cmx-skips", 1, SkipListener);

}  // namespace

namespace cmx::test {

void skip(const std::string& why) {
  SkipLedger& l = ledger();
  if (l.why.find(why) != std::string::npos) return;  // said already (a skip inside a loop)
  std::cout << "SKIPPED: " << l.running << ": " << why << std::endl;
  l.why += (l.why.empty() ? "" : "; ") + why;
}

std::filesystem::path shared_dir() {
  const char* set = std::getenv("CMX_SHARED_DIR");
  return set && *set ? std::filesystem::path(set) : std::filesystem::path(CMX_SHARED_DIR);
}

bool have_shared(const std::filesystem::path& relative) {
  const std::filesystem::path p = shared_dir() / relative;
  if (std::filesystem::exists(p)) return true;
  skip("no " + p.string());
  return false;
}

}  // namespace cmx::test

int main(int argc, char** argv) {
  doctest::Context context(argc, argv);
  const int status = context.run();
  if (context.shouldExit()) return status;
  const SkipLedger& l = ledger();
  if (!l.skipped.empty()) {
    std::cout << "[doctest] skipped at run time (not passed): " << l.skipped.size() << " test case(s)\n";
    for (const Skipped& s : l.skipped) std::cout << "SKIPPED: " << s.test_case << ": " << s.why << "\n";
  }
  const bool lone_skip = status == 0 && l.test_cases_run == 1 && l.skipped.size() == 1;
  return lone_skip ? CMX_TEST_SKIP_CODE : status;
}
