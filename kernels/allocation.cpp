#include "kernels/allocation.h"

#include <flint/flint.h>
#include <gmp.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>

namespace tmcert {
namespace {

// Registered output files (remove_on_fatal_exit): plain atomics, read by
// the handlers without allocating or locking.
constexpr int kMaxRegistered = 16;
std::atomic<const char*> g_registered[kMaxRegistered];

void remove_registered() {
  for (auto& slot : g_registered)
    if (const char* path = slot.exchange(nullptr)) ::unlink(path);
}

[[noreturn]] void fatal_exit(const char* message, std::size_t length) {
  // No allocation, no stdio: only unlink(2), write(2) and _exit(2), which
  // are safe wherever this is reached.
  remove_registered();
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, length);
  ::_exit(4);
}

[[noreturn]] void out_of_memory() {
  static const char message[] = "tmcert: out of memory\n";
  fatal_exit(message, sizeof message - 1);
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

// The reserve for unwinding (see allocation.h): address space only, mapped
// without access and never touched (so it costs no memory), given back at
// the first failed C++ allocation.  Mapped and unmapped directly, not
// through malloc: an allocator that keeps freed address space for itself
// (tcmalloc, which the command links: CMakeLists.txt) would keep a freed
// reserve and hand it out again, beyond the limit it was taken within.
std::atomic<void*> g_reserve{nullptr};
std::atomic<std::size_t> g_reserve_bytes{0};
constexpr std::size_t kMaxReserve = std::size_t{64} << 20;

void give_back_reserve() {
  if (void* p = g_reserve.exchange(nullptr)) ::munmap(p, g_reserve_bytes.load());
}

void take_reserve(std::size_t bytes) {
  give_back_reserve();
  // Smaller when the system refuses (a low limit set from outside).
  for (; bytes >= (std::size_t{1} << 20); bytes /= 2) {
    void* p = ::mmap(nullptr, bytes, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p != MAP_FAILED) {
      g_reserve_bytes = bytes;
      g_reserve = p;
      return;
    }
  }
}

void release_reserve_and_throw() {
  give_back_reserve();
  throw std::bad_alloc();
}

[[noreturn]] void on_terminate() {
  static const char internal[] = "tmcert: internal error (an exception that could not be handled)\n";
  bool memory = false;
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      memory = true;
    } catch (...) {
    }
  }
  if (memory) out_of_memory();
  fatal_exit(internal, sizeof internal - 1);
}

}  // namespace

void install_allocation_failure_handlers() {
  mp_set_memory_functions(checked_malloc, gmp_realloc, gmp_free);
  __flint_set_memory_functions(checked_malloc, checked_calloc, checked_realloc, std::free);
  // The reserve: an eighth of a limit set from outside (ulimit -v), at
  // most 64 MiB.
  struct rlimit limit;
  std::size_t reserve = kMaxReserve;
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur / 8 < reserve)
    reserve = static_cast<std::size_t>(limit.rlim_cur / 8);
  take_reserve(reserve);
  std::set_new_handler(release_reserve_and_throw);
  std::set_terminate(on_terminate);
}

bool limit_address_space(unsigned long long mebibytes) {
  if (mebibytes == 0 || mebibytes > (1ull << 40)) return false;
  struct rlimit limit;
  if (::getrlimit(RLIMIT_AS, &limit) != 0) return false;
  const rlim_t bytes = static_cast<rlim_t>(mebibytes) << 20;
  if (limit.rlim_max != RLIM_INFINITY && bytes > limit.rlim_max) return false;
  limit.rlim_cur = bytes;
  if (::setrlimit(RLIMIT_AS, &limit) != 0) return false;
  // The reserve within the new limit: given back first, then taken again
  // at its size (the old one may not fit).
  if (g_reserve.load()) take_reserve(std::min<std::size_t>(kMaxReserve, static_cast<std::size_t>(bytes / 8)));
  return true;
}

bool remove_on_fatal_exit(const char* path) {
  for (auto& slot : g_registered) {
    const char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, path)) return true;
  }
  return false;
}

void keep_on_fatal_exit(const char* path) {
  for (auto& slot : g_registered) {
    const char* expected = path;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

}  // namespace tmcert
