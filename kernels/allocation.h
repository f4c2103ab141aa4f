// Running out of memory, honestly (docs/scene-format.md "Limits"): GMP
// (and MPFR, which allocates through GMP) and FLINT/Arb abort the process
// when an allocation fails, which would be a crash.  After
// install_allocation_failure_handlers(), a failed allocation in any of them
// writes "tmcert: out of memory" to stderr and ends the process with exit
// code 4 (internal error or resource limit) at once, before any verdict is
// printed (a verdict is printed only after the whole computation).  C++
// allocations throw std::bad_alloc, which the command line reports the same
// way.
//
// Unwinding from a std::bad_alloc needs memory too: destroying an
// nlohmann::json array or object allocates (its destructor, noexcept,
// moves the children onto a heap stack to avoid deep recursion), so a
// large document dropped while memory is exhausted threw from a noexcept
// destructor, which is std::terminate (the certificate writer's abort,
// exit 134).  The handlers therefore keep a reserve of address space,
// released by the new-handler at the first failed C++ allocation before
// std::bad_alloc is thrown, so that unwinding can allocate; and a
// terminate handler that still reaches std::terminate (an exception in a
// noexcept function or a thread) ends the process as above (exit 4, "out
// of memory" for std::bad_alloc, "internal error" otherwise) instead of
// aborting.  Every end of the process through these handlers first removes
// the output files registered with remove_on_fatal_exit().
#pragma once

namespace tmcert {

void install_allocation_failure_handlers();

// Limits the process's address space to `mebibytes` MiB (RLIMIT_AS), so
// that a run that would need more fails as above instead of exhausting the
// machine.  Returns false when the system refuses the limit.  The reserve
// for unwinding is taken inside the limit (an eighth of it, at most 64 MiB).
bool limit_address_space(unsigned long long mebibytes);

// Output files that an end of the process through the handlers above must
// remove (a file being written, partial): `path` must stay valid until
// keep_on_fatal_exit(path) (the same pointer).  At most 16 at a time; more
// are not registered (and false is returned).
bool remove_on_fatal_exit(const char* path);
void keep_on_fatal_exit(const char* path);

}  // namespace tmcert
