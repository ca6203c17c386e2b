#pragma once
// A whole episode in one call: plan (or take the given plan), drive it in the Bullet simulation
// (once per realisation), judge it (Verdict.h), write its files and film it. Data in
// (EpisodeRequest.h), data out (EpisodeOutcome.h); nothing printed, nothing global. The command
// line's plan, run and render, every sweep episode and Python's plan() and run() are this call.
//
//   auto world = std::make_shared<const parksim::World>(parksim::loadWorld("worlds/head_in.yaml"));
//   parksim::EpisodeRequest request;
//   request.world = world;
//   request.out_dir = "out/demo";
//   const parksim::EpisodeOutcome outcome = parksim::runEpisodePipeline(request);
//   if (!outcome.verdict.met()) std::puts(outcome.verdict.reason.c_str());
//
// Expected outcomes (an unsolved plan, a contact, a missed goal) are the verdict's status; bad
// input throws parksim::Error before anything is written (checkEpisodeRequest), and a machine
// without OpenGL throws EnvironmentError when filming or drawing is asked for.

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodeOutcome.h"
#include "parksim/pipeline/EpisodeRequest.h"

namespace parksim {

EpisodeOutcome runEpisodePipeline(const EpisodeRequest& request);

/// The outcome of `request` when its user code failed where the pipeline could not see it end
/// (it crashed or hung its worker process: UserCodeIsolation.h): `error`'s verdict, the setup,
/// tolerance and plan summary the pipeline would give (a planner's failure as plan.json records
/// one, a given plan's statistics), and for a request that drives, metrics.json's content with
/// the verdict. Nothing is written, nothing was driven; a plan made before a controller failed
/// is lost with its process.
EpisodeOutcome userCodeFailureOutcome(const EpisodeRequest& request, const UserCodeError& error);

}  // namespace parksim
