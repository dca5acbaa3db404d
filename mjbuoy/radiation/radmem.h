// radmem: the panel solver's memory, estimated before it allocates, and
// what the process may still allocate (docs/robustness.md, "Radiation")
#ifndef MJBUOY_RADMEM_H_
#define MJBUOY_RADMEM_H_

#include <string>

namespace mjb {

// bytes panelSolve holds at its peak for n unknowns (nb body panels, the
// rest lid) solving nconc frequencies at once: the four real Rankine
// matrices (16 n^2 + 16 nb n), the infinite-frequency solve (32 nb^2) and
// per frequency five dense complex n x n matrices at its peak (the wave
// parts WS and WD, the system, its LU and the real sums it is built from:
// 80 n^2; panel.cc solveOmega)
double panelSolveBytes(double n, double nb, int nconc);

// frequencies panelSolve solves at once for nw of them: its worker
// threads (panel.cc parallelRows: the hardware's, at most 8)
int panelConcurrency(int nw);

// bytes this process may still allocate: the least of the system's
// MemAvailable (/proc/meminfo), the cgroup's memory.max less
// memory.current, and RLIMIT_AS less the address space in use; *what
// names the bound that gave it. INFINITY (what "") when none is known
double memoryAvailable(std::string* what);

// "" when panelSolve of n unknowns (nb body panels, nw frequencies) fits
// in memoryAvailable, else the sentence why not, with both figures
std::string panelMemoryCheck(int n, int nb, int nw);

}  // namespace mjb

#endif  // MJBUOY_RADMEM_H_
