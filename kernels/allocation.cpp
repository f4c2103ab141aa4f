#include "kernels/allocation.h"

#include <flint/flint.h>
#include <gmp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace tmcert {
namespace {

[[noreturn]] void out_of_memory() {
  // No allocation, no stdio: only write(2) and _exit(2) are safe here.
  static const char message[] = "tmcert: out of memory\n";
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(4);
}

void* checked_malloc(std::size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) out_of_memory();
  return p;
}

void* checked_calloc(std::size_t count, std::size_t size) {
  void* p = std::calloc(count ? count : 1, size ? size : 1);
  if (!p) out_of_memory();
  return p;
}

void* checked_realloc(void* old, std::size_t n) {
  void* p = std::realloc(old, n ? n : 1);
  if (!p) out_of_memory();
  return p;
}

// GMP's signatures: reallocate and free also get the old size.
void* gmp_realloc(void* old, std::size_t, std::size_t n) { return checked_realloc(old, n); }
void gmp_free(void* p, std::size_t) { std::free(p); }

}  // namespace

void install_allocation_failure_handlers() {
  mp_set_memory_functions(checked_malloc, gmp_realloc, gmp_free);
  __flint_set_memory_functions(checked_malloc, checked_calloc, checked_realloc, std::free);
}

bool limit_address_space(unsigned long long mebibytes) {
  if (mebibytes == 0 || mebibytes > (1ull << 40)) return false;
  struct rlimit limit;
  if (::getrlimit(RLIMIT_AS, &limit) != 0) return false;
  const rlim_t bytes = static_cast<rlim_t>(mebibytes) << 20;
  if (limit.rlim_max != RLIM_INFINITY && bytes > limit.rlim_max) return false;
  limit.rlim_cur = bytes;
  return ::setrlimit(RLIMIT_AS, &limit) == 0;
}

}  // namespace tmcert
