#include "parksim/rl/StepPool.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

#include "parksim/core/Error.h"
#include "parksim/core/NumberFormat.h"

namespace parksim {

namespace {

void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();  // yields the core's resources to its sibling hyper-thread
#endif
}

// Polls until `value` differs from `old`, for at most `spin`, then sleeps on it (C++20 atomic
// wait: a futex on Linux). Returns the new value.
std::uint64_t awaitChange(const std::atomic<std::uint64_t>& value, std::uint64_t old,
                          std::chrono::nanoseconds spin) {
  const auto until = std::chrono::steady_clock::now() + spin;
  for (int polls = 0;; ++polls) {
    const std::uint64_t now = value.load(std::memory_order_acquire);
    if (now != old) return now;
    if (polls % 64 == 63 && std::chrono::steady_clock::now() >= until) break;
    relax();
  }
  for (;;) {
    value.wait(old, std::memory_order_acquire);
    const std::uint64_t now = value.load(std::memory_order_acquire);
    if (now != old) return now;
  }
}

}  // namespace

struct StepPool::Impl {
  // One per worker, on its own cache line: the caller publishes a generation, the worker
  // reports it done.
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> start{0};
    std::atomic<std::uint64_t> done{0};
  };

  explicit Impl(const StepPoolDef& d)
      : threads(d.threads),
        spin(std::chrono::nanoseconds(static_cast<long long>(d.spin_s * 1e9))),
        slots(static_cast<std::size_t>(d.threads - 1)) {
    workers.reserve(slots.size());
    for (std::size_t w = 0; w < slots.size(); ++w) {
      workers.emplace_back([this, w] { serve(w); });
    }
  }

  ~Impl() {
    stopping.store(true, std::memory_order_relaxed);
    ++generation;
    for (Slot& slot : slots) {
      slot.start.store(generation, std::memory_order_release);
      slot.start.notify_one();
    }
    for (std::thread& t : workers) t.join();
  }

  // Items of thread `t` (0: the caller) in this generation.
  void drain(std::size_t t) {
    for (std::size_t i = t; i < count; i += static_cast<std::size_t>(threads)) {
      try {
        (*work)(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  }

  void serve(std::size_t w) {
    Slot& slot = slots[w];
    std::uint64_t seen = 0;
    for (;;) {
      seen = awaitChange(slot.start, seen, spin);
      if (stopping.load(std::memory_order_relaxed)) return;
      drain(w + 1);
      slot.done.store(seen, std::memory_order_release);
      slot.done.notify_one();
    }
  }

  int threads;
  std::chrono::nanoseconds spin;
  std::vector<Slot> slots;
  std::vector<std::thread> workers;
  std::atomic<bool> stopping{false};
  std::uint64_t generation = 0;
  // The current run's work, written before a generation is published (release) and read by
  // the workers after they see it (acquire).
  const std::function<void(std::size_t)>* work = nullptr;
  std::size_t count = 0;
  std::vector<std::exception_ptr> errors;
};

StepPool::StepPool(const StepPoolDef& def) {
  if (def.threads < 1) {
    throw Error("step pool: threads must be at least 1, got " + std::to_string(def.threads));
  }
  if (!(def.spin_s >= 0.0 && def.spin_s <= 1.0)) {
    throw Error("step pool: spin_s must be in [0, 1] s, got " + formatGeneral(def.spin_s));
  }
  impl_ = std::make_unique<Impl>(def);
}

StepPool::~StepPool() = default;

int StepPool::threads() const { return impl_->threads; }

void StepPool::run(std::size_t count, const std::function<void(std::size_t)>& work) {
  Impl& d = *impl_;
  d.work = &work;
  d.count = count;
  d.errors.assign(count, nullptr);
  // Workers without items this time are not woken.
  const std::size_t busy = std::min(d.slots.size(), count > 0 ? count - 1 : 0);
  const std::uint64_t generation = ++d.generation;
  for (std::size_t w = 0; w < busy; ++w) {
    d.slots[w].start.store(generation, std::memory_order_release);
    d.slots[w].start.notify_one();
  }
  d.drain(0);
  for (std::size_t w = 0; w < busy; ++w) {
    std::uint64_t done = d.slots[w].done.load(std::memory_order_acquire);
    while (done != generation) done = awaitChange(d.slots[w].done, done, d.spin);
  }
  for (const std::exception_ptr& e : d.errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace parksim
