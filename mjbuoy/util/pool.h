// pool: persistent worker threads for the cpu backend, created at attach
#ifndef MJBUOY_POOL_H_
#define MJBUOY_POOL_H_

namespace mjb {

struct Pool;

// start n worker threads; nullptr if none could be started
Pool* poolMake(int n);

// stop and join the workers
void poolFree(Pool* p);

// run fn(arg, c, slot) for every chunk c in [0, nc): the calling thread
// (slot 0) and the workers (slots 1 .. n) claim chunks in order until none
// is left, so a worker the OS does not schedule promptly costs at most the
// chunk it holds. Returns when all chunks are done. Returns false at once,
// running nothing, when another thread is using the pool (the caller then
// does the work itself). No allocation.
bool poolRun(Pool* p, void (*fn)(void*, int, int), void* arg, int nc);

}  // namespace mjb

#endif  // MJBUOY_POOL_H_
