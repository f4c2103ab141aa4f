// Running out of memory, honestly (docs/scene-format.md "Limits"): GMP
// (and MPFR, which allocates through GMP) and FLINT/Arb abort the process
// when an allocation fails, which would be a crash.  After
// install_allocation_failure_handlers(), a failed allocation in any of them
// writes "tmcert: out of memory" to stderr and ends the process with exit
// code 4 (internal error or resource limit) at once, before any verdict is
// printed (a verdict is printed only after the whole computation).  C++
// allocations throw std::bad_alloc, which the command line reports the same
// way.
#pragma once

namespace tmcert {

void install_allocation_failure_handlers();

// Limits the process's address space to `mebibytes` MiB (RLIMIT_AS), so
// that a run that would need more fails as above instead of exhausting the
// machine.  Returns false when the system refuses the limit.
bool limit_address_space(unsigned long long mebibytes);

}  // namespace tmcert
