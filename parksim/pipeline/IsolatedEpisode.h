#pragma once
// A whole episode (runEpisodePipeline) in a watched worker process (UserCodeIsolation.h), for a
// front end whose user code runs in its own process (Python's run() and plan() with
// isolate=True): a planner or controller that crashes, or hangs past request.limits, ends the
// worker, not the caller, and the outcome's verdict is its planner_error or controller_error.
// The worker sends its outcome back as bytes (encodeOutcome), which only a process forked from
// the same program reads (decodeOutcome).
//
//   parksim::EpisodeRequest request = ...;      // a plugin's or a Python object's components
//   request.limits.planner_s = 5.0;
//   const parksim::EpisodeOutcome out = parksim::runEpisodeIsolated(request);
//   // out.verdict.status == kPlannerError: "planner hanging-planner ran past its time limit of
//   // 5 s (its process was killed)"

#include <memory>
#include <string>
#include <string_view>

#include "parksim/pipeline/EpisodeOutcome.h"
#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/usercode/UserCodeIsolation.h"

namespace parksim {

/// runEpisodePipeline(request) in a worker forked from the calling thread (`hooks` around the
/// fork: an embedding interpreter's), under request.limits. The same outcome as in this
/// process, except that user code that crashes or hangs gives userCodeFailureOutcome
/// (EpisodePipeline.h): its verdict, nothing driven, nothing more written (the frames of a film
/// begun remain). Bad input throws Error before the fork (checkEpisodeRequest, a plugin's
/// components made in a watched worker of their own); an Error in the worker is thrown here.
EpisodeOutcome runEpisodeIsolated(const EpisodeRequest& request, const ForkHooks& hooks = {});

/// The outcome as bytes for a process forked from this one (the same build): everything but
/// the world, the plan's setup, the execution and the tolerance, which the reader has.
std::string encodeOutcome(const EpisodeOutcome& outcome);

/// encodeOutcome's bytes back, with the reader's world, setup, execution (set when driven) and
/// tolerance. Throws Error on bytes encodeOutcome did not make.
EpisodeOutcome decodeOutcome(std::string_view bytes, std::shared_ptr<const World> world,
                             const PlanSetup& setup, const ExecutionDef& execution,
                             const TrackingTolerance& tolerance);

}  // namespace parksim
