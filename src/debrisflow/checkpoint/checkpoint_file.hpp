#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace debrisflow::checkpoint {

// Checkpoint files: OUT/checkpoint/step_<step>.dfc, a 24-byte header (magic, format
// version, CRC-32 of the payload, payload size) and the payload (an Archive's bytes).
// 2: contact slots without rolling memory; 3: the bodies' boundary particles and the grains'
// reaction on them in the sph-rigid and dem-rigid couplings' sections
inline constexpr std::uint32_t format_version = 3;

// Writes `payload` to `path` safely: into path + ".tmp", flushed to disk (fsync), then renamed
// over `path`, so a kill at any moment leaves either the old file set or the new one.
// Fault injection for the tests: with DEBRISFLOW_CHECKPOINT_KILL_AFTER_BYTES=n in the
// environment the process kills itself (SIGKILL) after writing n bytes of the temporary file
// of its second checkpoint (the first one stays complete, to restart from).
void write_file(const std::string& path, const std::vector<char>& payload);

// The payload of a checkpoint file; CheckpointError naming the file when it is missing,
// truncated, of another format version or fails its checksum.
std::vector<char> read_file(const std::string& path);

// File name of the checkpoint after `step` steps.
std::string file_name(long step);

// Checkpoint files (*.dfc) in `dir`, newest (most steps) first; temporaries are ignored.
std::vector<std::string> list(const std::string& dir);

// Deletes all but the `keep` newest checkpoint files in `dir` and any temporary left by a kill.
void prune(const std::string& dir, int keep);

} // namespace debrisflow::checkpoint
