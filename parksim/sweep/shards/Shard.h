#pragma once
// A deterministic part of a sweep: shard I of N holds the episodes whose position in the
// canonical order (ascending episode id) is I modulo N. Every episode is in exactly one shard,
// the shards differ in size by at most one, and the same spec gives the same shards on every
// machine.

#include <string>
#include <vector>

#include "parksim/sweep/spec/EpisodeExpansion.h"

namespace parksim {

struct Shard {
  int index = 0;  ///< I, from 0
  int count = 1;  ///< N >= 1
};

/// Parses "I/N" (0 <= I < N). Throws Error otherwise.
Shard parseShard(const std::string& text);

/// The episodes of `shard`; `episodes` must be in canonical order (expandEpisodes' result).
std::vector<SweepEpisode> selectShard(const std::vector<SweepEpisode>& episodes,
                                      const Shard& shard);

}  // namespace parksim
