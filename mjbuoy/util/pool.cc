// a minimal fork-join pool: one job at a time, chunks claimed from a
// counter. Workers spin a little before they sleep: a step of one boat
// runs three jobs a few tens of microseconds apart (cpu.cc), and waking a
// sleeping thread costs about as much as one of them (measured 20-40 us)
#include "util/pool.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace mjb {

// how long an idle worker polls for the next job before it sleeps [us]:
// longer than the gap between one step's jobs and between two steps of a
// small scene, short enough that a pool between bursts of steps gives its
// core back at once
const int kSpinUs = 200;

// ctl packs a job's state in one word so a worker joins it atomically:
// bits 32-63 the job's number, bit 31 open (the job still takes workers),
// bits 0-30 the workers inside it
const uint64_t kOpen = uint64_t(1) << 31, kActive = kOpen - 1;

struct Pool {
  std::mutex busy;                    // held by the caller of the running job
  std::mutex mu;                      // with cv: sleeping workers
  std::condition_variable cv;
  std::atomic<uint64_t> ctl{0};
  std::atomic<int> sleepers{0};
  std::atomic<bool> quit{false};
  std::atomic<int> next{0};           // next chunk to claim
  // the job, written before it opens (release) and read after joining
  void (*fn)(void*, int, int) = nullptr;
  void* arg = nullptr;
  int nc = 0;
  std::vector<std::thread> th;
};

static void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

// claim and run chunks until none is left
static void drain(Pool* p, void (*fn)(void*, int, int), void* arg, int nc, int slot) {
  for (int c; (c = p->next.fetch_add(1, std::memory_order_relaxed)) < nc;) fn(arg, c, slot);
}

// join an open job numbered other than seen: true when this worker is in
static bool join(Pool* p, uint64_t* seen) {
  uint64_t c = p->ctl.load(std::memory_order_acquire);
  while ((c & kOpen) && (c >> 32) != *seen) {
    if (p->ctl.compare_exchange_weak(c, c + 1, std::memory_order_acquire)) {
      *seen = c >> 32;
      return true;
    }
  }
  return false;
}

// sleep until a job other than seen opens, or the pool quits. The
// sleepers count and ctl are both sequentially consistent, so poolRun
// (which stores ctl, then reads sleepers) either sees this worker asleep
// and notifies it, or this worker sees the new job before it sleeps
static void sleep(Pool* p, uint64_t seen) {
  std::unique_lock<std::mutex> lk(p->mu);
  p->sleepers.fetch_add(1);
  p->cv.wait(lk, [&] {
    const uint64_t c = p->ctl.load();
    return p->quit.load() || ((c & kOpen) && (c >> 32) != seen);
  });
  p->sleepers.fetch_sub(1);
}

static void work(Pool* p, int slot) {
  uint64_t seen = 0;
  for (;;) {
    auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; !join(p, &seen); i++) {
      if (p->quit.load(std::memory_order_relaxed)) return;
      relax();
      if ((i & 63) == 63 &&
          std::chrono::steady_clock::now() - t0 > std::chrono::microseconds(kSpinUs)) {
        sleep(p, seen);
        if (p->quit.load()) return;
        t0 = std::chrono::steady_clock::now();
      }
    }
    drain(p, p->fn, p->arg, p->nc, slot);
    p->ctl.fetch_sub(1, std::memory_order_release);
  }
}

Pool* poolMake(int n) {
  Pool* p = new Pool;
  try {
    for (int i = 0; i < n; i++) p->th.emplace_back(work, p, i + 1);
  } catch (...) {
    poolFree(p);
    return nullptr;
  }
  if (p->th.empty()) {
    delete p;
    return nullptr;
  }
  return p;
}

void poolFree(Pool* p) {
  if (!p) return;
  {
    std::lock_guard<std::mutex> lk(p->mu);
    p->quit.store(true);
  }
  p->cv.notify_all();
  for (std::thread& t : p->th) t.join();
  delete p;
}

bool poolRun(Pool* p, void (*fn)(void*, int, int), void* arg, int nc) {
  std::unique_lock<std::mutex> own(p->busy, std::try_to_lock);
  if (!own.owns_lock()) return false;
  // no worker is inside a job here (the last one ended with none inside)
  p->fn = fn;
  p->arg = arg;
  p->nc = nc;
  p->next.store(0, std::memory_order_relaxed);
  const uint64_t job = (p->ctl.load(std::memory_order_relaxed) >> 32) + 1;
  p->ctl.store((job << 32) | kOpen);  // sequentially consistent: see sleep()
  if (p->sleepers.load() > 0) {
    std::lock_guard<std::mutex> lk(p->mu);
    p->cv.notify_all();
  }
  drain(p, fn, arg, nc, 0);
  // close the job: no worker joins after this; wait for those inside
  uint64_t c = p->ctl.fetch_and(~kOpen, std::memory_order_acq_rel) & ~kOpen;
  while (c & kActive) {
    relax();
    c = p->ctl.load(std::memory_order_acquire);
  }
  return true;
}

}  // namespace mjb
