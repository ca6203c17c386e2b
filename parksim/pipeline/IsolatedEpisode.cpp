#include "parksim/pipeline/IsolatedEpisode.h"

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"

namespace parksim {

namespace {

// T is U, const or not: one list of a type's parts serves writing (const) and reading.
template <class T, class U>
concept Is = std::same_as<std::remove_const_t<T>, U>;

// Each type's parts, in order. Plain data (trivially copyable: numbers, enums, poses, rows) is
// copied as bytes; the writer and the reader are forks of one program, so their layouts agree.
template <class A, Is<Trajectory> T>
void parts(A& a, T& t) {
  a(t.points);
}

template <class A, Is<PlanResult> T>
void parts(A& a, T& r) {
  a(r.status, r.message, r.trajectory, r.waypoints, r.tree_edges, r.cost, r.objective,
    r.duration_lower_bound_s, r.free_space_bound_s, r.cost_history, r.stats);
}

template <class A, Is<ContactEvent> T>
void parts(A& a, T& c) {
  a(c.t_s, c.obstacle_index, c.body);
}

template <class A, Is<ParkedRobotDisplacement> T>
void parts(A& a, T& p) {
  a(p.name, p.max_m, p.final_m);
}

// Every field of EpisodeMetrics (sim/EpisodeMetrics.h); IsolatedEpisodeTest compares every
// metrics.json key of a lab episode sent through here.
template <class A, Is<EpisodeMetrics> T>
void parts(A& a, T& m) {
  a(m.tracking, m.controller, m.controller_error, m.max_pos_err_m, m.rms_pos_err_m,
    m.final_pos_err_m, m.max_heading_err_deg, m.rms_heading_err_deg, m.final_heading_err_deg,
    m.final_pose, m.goal_pos_err_m, m.goal_heading_err_deg, m.goal_reached, m.contacts,
    m.first_contact_t_s, m.first_contact_body, m.contact_events, m.parked,
    m.max_parked_displacement_m, m.plan_duration_s, m.sim_time_s, m.steps, m.time_step_s,
    m.ended_at_rest, m.wall_time_s);
  a(m.realism, m.noise_seed, m.estimator, m.max_est_pos_err_m, m.rms_est_pos_err_m,
    m.max_est_heading_err_deg, m.final_est_pos_err_m, m.max_slip_mps, m.rms_slip_mps,
    m.slip_fraction, m.max_motor_torque_nm, m.max_motor_effort, m.true_left_radius_m,
    m.true_right_radius_m, m.true_track_m, m.left_motor_gain, m.right_motor_gain,
    m.pose_samples_taken, m.pose_samples_dropped, m.pose_samples_received);
}

template <class A, Is<EpisodeResult> T>
void parts(A& a, T& e) {
  a(e.metrics, e.rows, e.pose_samples);
}

template <class A, Is<Verdict> T>
void parts(A& a, T& v) {
  a(v.status, v.reason);
}

template <class A, Is<RealisationOutcome> T>
void parts(A& a, T& r) {
  a(r.noise_seed, r.metrics, r.verdict);
}

template <class A, Is<VideoOutcome> T>
void parts(A& a, T& v) {
  a(v.status, v.path, v.message);
}

template <class A, Is<RecordingResult> T>
void parts(A& a, T& r) {
  a(r.frames, r.lot_drawings, r.frames_dir, r.video, r.gif, r.message);
}

// What the worker knows and the caller does not (the world, setup, execution and tolerance are
// the caller's own).
template <class A, Is<EpisodeOutcome> T>
void parts(A& a, T& o) {
  a(o.plan, o.trajectory, o.plan_summary, o.episode, o.realisations, o.verdict, o.metrics,
    o.recording, o.files);
}

class Writer {
 public:
  template <class... T>
  void operator()(const T&... values) {
    (put(values), ...);
  }
  std::string& bytes() { return out_; }

 private:
  void raw(const void* data, std::size_t size) {
    out_.append(static_cast<const char*>(data), size);
  }
  void count(std::size_t n) {
    const auto v = static_cast<std::uint64_t>(n);
    raw(&v, sizeof v);
  }
  void put(const std::string& s) {
    count(s.size());
    raw(s.data(), s.size());
  }
  // JSON as CBOR: exact doubles (NaN included), any text.
  void put(const nlohmann::json& j) {
    const std::vector<std::uint8_t> cbor =
        j.is_null() ? std::vector<std::uint8_t>{} : nlohmann::json::to_cbor(j);
    count(cbor.size());
    raw(cbor.data(), cbor.size());
  }
  template <class T>
  void put(const std::vector<T>& v) {
    count(v.size());
    if constexpr (std::is_trivially_copyable_v<T>) {
      raw(v.data(), v.size() * sizeof(T));
    } else {
      for (const T& x : v) put(x);
    }
  }
  template <class T>
  void put(const std::optional<T>& o) {
    put(o.has_value());
    if (o) put(*o);
  }
  template <class T>
  void put(const T& x) {
    if constexpr (std::is_trivially_copyable_v<T>) {
      raw(&x, sizeof x);
    } else {
      parts(*this, x);
    }
  }

  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  template <class... T>
  void operator()(T&... values) {
    (get(values), ...);
  }
  bool done() const { return in_.empty(); }

 private:
  [[noreturn]] static void bad() { throw Error("an episode outcome's bytes are cut short"); }
  void raw(void* data, std::size_t size) {
    if (size > in_.size()) bad();
    if (size == 0) return;  // an empty vector's data() may be null, which memcpy may not take
    std::memcpy(data, in_.data(), size);
    in_.remove_prefix(size);
  }
  // A count of items of `size` bytes each, no more than are left.
  std::size_t count(std::size_t size) {
    std::uint64_t n = 0;
    raw(&n, sizeof n);
    if (n > in_.size() / std::max<std::size_t>(size, 1)) bad();
    return static_cast<std::size_t>(n);
  }
  void get(std::string& s) {
    s.assign(in_.substr(0, count(1)));
    in_.remove_prefix(s.size());
  }
  void get(nlohmann::json& j) {
    const std::size_t n = count(1);
    j = n == 0 ? nlohmann::json() : nlohmann::json::from_cbor(in_.substr(0, n));
    in_.remove_prefix(n);
  }
  template <class T>
  void get(std::vector<T>& v) {
    if constexpr (std::is_trivially_copyable_v<T>) {
      v.resize(count(sizeof(T)));
      raw(v.data(), v.size() * sizeof(T));
    } else {
      v.resize(count(1));
      for (T& x : v) get(x);
    }
  }
  template <class T>
  void get(std::optional<T>& o) {
    bool has = false;
    get(has);
    o.reset();
    if (has) get(o.emplace());
  }
  template <class T>
  void get(T& x) {
    if constexpr (std::is_trivially_copyable_v<T>) {
      raw(&x, sizeof x);
    } else {
      parts(*this, x);
    }
  }

  std::string_view in_;
};

}  // namespace

std::string encodeOutcome(const EpisodeOutcome& outcome) {
  Writer w;
  parts(w, outcome);
  return std::move(w.bytes());
}

EpisodeOutcome decodeOutcome(std::string_view bytes, std::shared_ptr<const World> world,
                             const PlanSetup& setup, const ExecutionDef& execution,
                             const TrackingTolerance& tolerance) {
  EpisodeOutcome out;
  Reader r(bytes);
  parts(r, out);
  if (!r.done()) throw Error("an episode outcome's bytes run on past its end");
  out.world = std::move(world);
  out.plan_setup = setup;
  if (out.driven()) out.execution = execution;
  out.tolerance = tolerance;
  return out;
}

EpisodeOutcome runEpisodeIsolated(const EpisodeRequest& request, const ForkHooks& hooks) {
  checkEpisodeRequest(request, {.limits = request.limits, .hooks = hooks, .isolate = true});
  const EpisodeSettings settings = resolveSettings(request);
  try {
    const std::string bytes = runIsolated(
        [&](UserCodeWatch& watch) {
          EpisodeRequest watched = request;
          watched.watch = &watch;
          return encodeOutcome(runEpisodePipeline(watched));
        },
        request.limits, hooks);
    return decodeOutcome(bytes, request.world, settings.plan, settings.execution,
                         settings.tolerance);
  } catch (const UserCodeError& e) {
    return userCodeFailureOutcome(request, e);
  }
}

}  // namespace parksim
