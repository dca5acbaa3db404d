// cpus: how many CPUs this process may run on. A batch scheduler (Slurm,
// cgroups, taskset) gives a job fewer CPUs than the node has; threads past
// the allocation only time-share and slow every step
#ifndef MJBUOY_UTIL_CPUS_H_
#define MJBUOY_UTIL_CPUS_H_

namespace mjb {

// the CPUs in this process's affinity mask (sched_getaffinity), at most
// SLURM_CPUS_PER_TASK when that is set; the core count where the OS cannot
// say; at least 1
int usableCpus();

}  // namespace mjb

#endif  // MJBUOY_UTIL_CPUS_H_
