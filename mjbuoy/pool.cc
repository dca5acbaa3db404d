// a minimal fork-join pool: one job at a time, chunks claimed from a counter
#include "pool.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace mjb {

struct Pool {
  std::mutex busy;                    // held by the caller of the running job
  std::mutex mu;                      // guards the fields below
  std::condition_variable go, done;
  void (*fn)(void*, int, int) = nullptr;
  void* arg = nullptr;
  int nc = 0;
  long gen = 0;                       // job counter; workers wait for it to change
  bool open = false;                  // the job still takes workers
  int active = 0;                     // workers inside the job
  bool quit = false;
  std::atomic<int> next{0};           // next chunk to claim
  std::vector<std::thread> th;
};

// claim and run chunks until none is left
static void drain(Pool* p, void (*fn)(void*, int, int), void* arg, int nc, int slot) {
  for (int c; (c = p->next.fetch_add(1, std::memory_order_relaxed)) < nc;) fn(arg, c, slot);
}

static void work(Pool* p, int slot) {
  long seen = 0;
  std::unique_lock<std::mutex> lk(p->mu);
  for (;;) {
    p->go.wait(lk, [&] { return p->quit || p->gen != seen; });
    if (p->quit) return;
    seen = p->gen;
    if (!p->open) continue;  // woke after the caller finished alone
    p->active++;
    void (*fn)(void*, int, int) = p->fn;
    void* arg = p->arg;
    int nc = p->nc;
    lk.unlock();
    drain(p, fn, arg, nc, slot);
    lk.lock();
    if (--p->active == 0) p->done.notify_one();
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
    p->quit = true;
  }
  p->go.notify_all();
  for (std::thread& t : p->th) t.join();
  delete p;
}

bool poolRun(Pool* p, void (*fn)(void*, int, int), void* arg, int nc) {
  std::unique_lock<std::mutex> own(p->busy, std::try_to_lock);
  if (!own.owns_lock()) return false;
  {
    std::lock_guard<std::mutex> lk(p->mu);
    p->fn = fn;
    p->arg = arg;
    p->nc = nc;
    p->next.store(0, std::memory_order_relaxed);
    p->open = true;
    p->gen++;
  }
  p->go.notify_all();
  drain(p, fn, arg, nc, 0);
  // no worker joins after this; wait for those inside to finish their chunk
  std::unique_lock<std::mutex> lk(p->mu);
  p->open = false;
  p->done.wait(lk, [&] { return p->active == 0; });
  return true;
}

}  // namespace mjb
