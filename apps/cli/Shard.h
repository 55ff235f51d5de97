// `--shard I/N` of render and bench (issue 33, docs/cli.md "On a cluster"): one task of a job
// array takes every N-th item of the work (frames of a recording, cases of a sweep), starting
// at item I − 1, so that N tasks started with I = 1 .. N together do the whole work once.
// Pure parsing, tested without GL.
#pragma once

#include <cstddef>
#include <string>

namespace manylights {

struct Shard {
    int index = 1;  // 1 .. count, as job arrays number their tasks (SLURM_ARRAY_TASK_ID)
    int count = 1;

    // Whether item `item` (0-based, in the order of the whole work) is this shard's.
    bool has(std::size_t item) const { return item % static_cast<std::size_t>(count) == std::size_t(index - 1); }
    bool isWhole() const { return count == 1; }
};

// "I/N" with 1 ≤ I ≤ N ≤ kMaxShards. Returns the problem as one line naming --shard, or an
// empty string; then `shard` holds it.
std::string parseShard(const std::string& text, Shard& shard);

// More tasks than any job array a scheduler accepts (Slurm's default MaxArraySize is 1001).
inline constexpr int kMaxShards = 1'000'000;

}  // namespace manylights
