#include "parksim/sweep/shards/Shard.h"

#include <cstdio>

#include "parksim/core/io/Error.h"

namespace parksim {

Shard parseShard(const std::string& text) {
  int index = -1;
  int count = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%d/%d%n", &index, &count, &used) != 2 ||
      used != static_cast<int>(text.size()) || count < 1 || index < 0 || index >= count) {
    throw Error("--shard: expected I/N with 0 <= I < N (e.g. 0/4), got '" + text + "'");
  }
  return {index, count};
}

std::vector<SweepEpisode> selectShard(const std::vector<SweepEpisode>& episodes,
                                      const Shard& shard) {
  std::vector<SweepEpisode> out;
  for (std::size_t i = static_cast<std::size_t>(shard.index); i < episodes.size();
       i += static_cast<std::size_t>(shard.count)) {
    out.push_back(episodes[i]);
  }
  return out;
}

}  // namespace parksim
