// a minimal fork-join pool: one job at a time, woken by a condition variable
#include "pool.h"

#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace mjb {

struct Pool {
  std::mutex busy;                    // held by the caller of the running job
  std::mutex mu;                      // guards the fields below
  std::condition_variable go, done;
  void (*fn)(void*, int) = nullptr;
  void* arg = nullptr;
  long gen = 0;                       // job counter; workers wait for it to change
  int left = 0;                       // workers still running the job
  bool quit = false;
  std::vector<std::thread> th;
};

static void work(Pool* p, int i) {
  long seen = 0;
  std::unique_lock<std::mutex> lk(p->mu);
  for (;;) {
    p->go.wait(lk, [&] { return p->quit || p->gen != seen; });
    if (p->quit) return;
    seen = p->gen;
    void (*fn)(void*, int) = p->fn;
    void* arg = p->arg;
    lk.unlock();
    fn(arg, i);
    lk.lock();
    if (--p->left == 0) p->done.notify_one();
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

bool poolRun(Pool* p, void (*fn)(void*, int), void* arg) {
  std::unique_lock<std::mutex> own(p->busy, std::try_to_lock);
  if (!own.owns_lock()) return false;
  {
    std::lock_guard<std::mutex> lk(p->mu);
    p->fn = fn;
    p->arg = arg;
    p->left = p->th.size();
    p->gen++;
  }
  p->go.notify_all();
  fn(arg, 0);
  std::unique_lock<std::mutex> lk(p->mu);
  p->done.wait(lk, [&] { return p->left == 0; });
  return true;
}

}  // namespace mjb
