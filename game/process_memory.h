// The process's resident memory, for long runs that must not grow (the soak run).
#pragma once

namespace qlight::game {

// Resident set size in MiB from /proc/self/statm; 0 where it cannot be read.
double residentMegabytes();

}  // namespace qlight::game
