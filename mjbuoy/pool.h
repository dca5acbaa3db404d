// pool: persistent worker threads for the cpu backend, created at attach
#ifndef MJBUOY_POOL_H_
#define MJBUOY_POOL_H_

namespace mjb {

struct Pool;

// start n worker threads; nullptr if none could be started
Pool* poolMake(int n);

// stop and join the workers
void poolFree(Pool* p);

// run fn(arg, i) for i = 0 .. n (n workers): i = 0 on the calling thread,
// the rest on the workers, and return when all are done. Returns false at
// once, running nothing, when another thread is using the pool (the caller
// then does the work itself). No allocation.
bool poolRun(Pool* p, void (*fn)(void*, int), void* arg);

}  // namespace mjb

#endif  // MJBUOY_POOL_H_
