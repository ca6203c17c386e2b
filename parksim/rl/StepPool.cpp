#include "parksim/rl/StepPool.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

namespace {

// The pool's state in one word, so that joining a run and closing it cannot cross: the
// generation of the last run, whether it is open to workers, and how many workers are inside.
constexpr std::uint64_t kInsideMask = 0xffffU;
constexpr std::uint64_t kOpen = std::uint64_t{1} << 16U;
constexpr std::uint64_t kStop = std::uint64_t{1} << 17U;
constexpr unsigned kGenerationShift = 18U;
constexpr int kMaxThreads = 1024;

std::uint64_t generationOf(std::uint64_t state) { return state >> kGenerationShift; }

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
  explicit Impl(const StepPoolDef& d)
      : threads(d.threads), spin(std::chrono::nanoseconds(static_cast<long long>(d.spin_s * 1e9))) {
    workers.reserve(static_cast<std::size_t>(threads - 1));
    for (int t = 1; t < threads; ++t) {
      workers.emplace_back([this, t] { serve(static_cast<std::size_t>(t)); });
    }
  }

  ~Impl() {
    state.fetch_or(kStop, std::memory_order_acq_rel);
    state.notify_all();
    for (std::thread& t : workers) t.join();
  }

  void attempt(std::size_t i) {
    if (claimed[i].exchange(1, std::memory_order_acq_rel) != 0) return;
    try {
      (*work)(i);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  }

  // Thread t's own items first, then (from the back, away from their owners' fronts) any item
  // nobody has started.
  void drain(std::size_t t) {
    for (std::size_t i = t; i < count; i += static_cast<std::size_t>(threads)) attempt(i);
    for (std::size_t i = count; i-- > 0;) attempt(i);
  }

  void serve(std::size_t t) {
    std::uint64_t seen = state.load(std::memory_order_acquire);
    std::uint64_t handled = 0;  // generation this worker last joined
    for (;;) {
      if ((seen & kStop) != 0) return;
      if ((seen & kOpen) != 0 && generationOf(seen) != handled) {
        if (!state.compare_exchange_weak(seen, seen + 1, std::memory_order_acq_rel,
                                         std::memory_order_acquire)) {
          continue;
        }
        handled = generationOf(seen);
        drain(t);
        seen = state.fetch_sub(1, std::memory_order_acq_rel) - 1;
        state.notify_all();  // the caller may be waiting for the last one out
        continue;
      }
      seen = awaitChange(state, seen, spin);
    }
  }

  int threads;
  std::chrono::nanoseconds spin;
  std::vector<std::thread> workers;
  std::atomic<std::uint64_t> state{0};
  std::uint64_t generation = 0;
  // The current run, written while the pool is closed and published by opening it (release);
  // workers read it after joining (acquire).
  const std::function<void(std::size_t)>* work = nullptr;
  std::size_t count = 0;
  std::vector<std::atomic<std::uint8_t>> claimed;
  std::vector<std::exception_ptr> errors;
};

StepPool::StepPool(const StepPoolDef& def) {
  if (def.threads < 1 || def.threads > kMaxThreads) {
    throw Error("step pool: threads must be in [1, " + std::to_string(kMaxThreads) + "], got " +
                std::to_string(def.threads));
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
  if (d.claimed.size() < count) d.claimed = std::vector<std::atomic<std::uint8_t>>(count);
  for (std::size_t i = 0; i < count; ++i) d.claimed[i].store(0, std::memory_order_relaxed);
  const std::uint64_t closed = ++d.generation << kGenerationShift;
  if (d.threads > 1 && count > 1) {
    d.state.store(closed | kOpen, std::memory_order_release);
    d.state.notify_all();
  }
  d.drain(0);
  // Every item is claimed now; close once the workers inside have finished theirs.
  std::uint64_t s = d.state.load(std::memory_order_acquire);
  while (s != closed) {
    if ((s & kInsideMask) == 0) {
      d.state.compare_exchange_weak(s, closed, std::memory_order_acq_rel,
                                    std::memory_order_acquire);
    } else {
      s = awaitChange(d.state, s, d.spin);
    }
  }
  for (const std::exception_ptr& e : d.errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace parksim
