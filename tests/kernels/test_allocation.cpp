// kernels/allocation: a failed allocation in GMP, or an exception that
// reaches std::terminate, ends the process with exit code 4 and one line on
// stderr, after removing the registered output files; at most 16 files are
// registered at a time.  The fatal paths run in a forked child.
#include "kernels/allocation.h"

#include <boost/test/unit_test.hpp>
#include <gmp.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <new>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;

#if defined(__SANITIZE_ADDRESS__)
#define TMCERT_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TMCERT_TEST_ASAN 1
#endif
#endif

namespace {

struct ChildEnd {
  int exit_code = -1;  // -1: did not exit normally
  std::string err;
  bool output_left = true;
};

// Runs `body` in a child with the handlers installed, stderr to a file and
// `output` registered for removal; the child ends with exit 0 if `body`
// returns.
ChildEnd run_child(const std::function<void(const char* output)>& body) {
  const fs::path dir = fs::temp_directory_path() / ("tmcert-allocation-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string err_path = (dir / "stderr").string(), output = (dir / "partial.json").string();
  std::ofstream(output) << "{\"partial\":";
  ChildEnd end;
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::FILE* f = std::freopen(err_path.c_str(), "w", stderr);
    if (!f) ::_exit(99);
    tmcert::install_allocation_failure_handlers();
    if (!tmcert::remove_on_fatal_exit(output.c_str())) ::_exit(98);
    body(output.c_str());
    ::_exit(0);
  }
  int status = 0;
  BOOST_REQUIRE(pid > 0);
  BOOST_REQUIRE(::waitpid(pid, &status, 0) == pid);
  if (WIFEXITED(status)) end.exit_code = WEXITSTATUS(status);
  std::ifstream in(err_path);
  end.err.assign(std::istreambuf_iterator<char>(in), {});
  end.output_left = fs::exists(output);
  fs::remove_all(dir);
  return end;
}

void throw_through_noexcept(const std::function<void()>& f) noexcept { f(); }

}  // namespace

BOOST_AUTO_TEST_SUITE(allocation)

BOOST_AUTO_TEST_CASE(at_most_sixteen_registered_files) {
  static const char names[17][8] = {"f0", "f1", "f2",  "f3",  "f4",  "f5",  "f6",  "f7", "f8",
                                    "f9", "f10", "f11", "f12", "f13", "f14", "f15", "f16"};
  for (int i = 0; i < 16; ++i) BOOST_TEST(tmcert::remove_on_fatal_exit(names[i]));
  BOOST_TEST(!tmcert::remove_on_fatal_exit(names[16]));
  tmcert::keep_on_fatal_exit(names[3]);  // frees one slot
  BOOST_TEST(tmcert::remove_on_fatal_exit(names[16]));
  BOOST_TEST(!tmcert::remove_on_fatal_exit(names[3]));
  for (int i = 0; i < 17; ++i) tmcert::keep_on_fatal_exit(names[i]);
  BOOST_TEST(tmcert::remove_on_fatal_exit(names[0]));  // all free again
  tmcert::keep_on_fatal_exit(names[0]);
}

BOOST_AUTO_TEST_CASE(kept_file_stays_at_a_normal_end) {
  const ChildEnd end = run_child([](const char* output) { tmcert::keep_on_fatal_exit(output); });
  BOOST_TEST(end.exit_code == 0);
  BOOST_TEST(end.err.empty());
  BOOST_TEST(end.output_left);
}

BOOST_AUTO_TEST_CASE(bad_alloc_through_terminate_is_exit_4) {
  const ChildEnd end = run_child([](const char*) { throw_through_noexcept([] { throw std::bad_alloc(); }); });
  BOOST_TEST(end.exit_code == 4);
  BOOST_TEST(end.err == "tmcert: out of memory\n");
  BOOST_TEST(!end.output_left);
}

BOOST_AUTO_TEST_CASE(other_exception_through_terminate_is_an_internal_error) {
  const ChildEnd end =
      run_child([](const char*) { throw_through_noexcept([] { throw std::runtime_error("boom"); }); });
  BOOST_TEST(end.exit_code == 4);
  BOOST_TEST(end.err.find("tmcert: internal error") == 0u);
  BOOST_TEST(!end.output_left);
}

#ifndef TMCERT_TEST_ASAN  // the sanitizer's allocator reports a huge allocation itself
BOOST_AUTO_TEST_CASE(failed_gmp_allocation_is_exit_4) {
  const ChildEnd end = run_child([](const char*) {
    if (!tmcert::limit_address_space(1024)) ::_exit(97);
    mpz_t x;
    mpz_init2(x, mp_bitcnt_t{1} << 36);  // 8 GiB of limbs: over the limit
    mpz_setbit(x, (mp_bitcnt_t{1} << 36) - 1);
    mpz_clear(x);
  });
  BOOST_TEST(end.exit_code == 4);
  BOOST_TEST(end.err == "tmcert: out of memory\n");
  BOOST_TEST(!end.output_left);
}
#endif

BOOST_AUTO_TEST_CASE(limit_refuses_zero_and_absurd_sizes) {
  BOOST_TEST(!tmcert::limit_address_space(0));
  BOOST_TEST(!tmcert::limit_address_space((1ull << 40) + 1));
}

BOOST_AUTO_TEST_SUITE_END()
