// Output files that are never half-written: an output folder, and files written atomically,
// so a run that fails, is interrupted or is killed (SIGKILL included) leaves each file absent,
// old and complete, or new and complete.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string_view>

namespace rice::experiments {

/// Creates `folder` (and parents); throws with the path on failure. Removes the hidden
/// temporaries `.<name>.partial-<pid>-<n>` that runs killed while using the fallback of
/// write_file_atomically left in it (those of processes still running stay).
void make_output_folder(const std::filesystem::path& folder);

/// Writes `bytes` to `path` so that `path` is, at every instant, absent, its old complete
/// content or the new complete content, even if the process is killed (SIGKILL included).
/// The bytes go to an unnamed file in the same folder (Linux O_TMPFILE); once complete, an
/// old `path` is unlinked and the unnamed file linked as `path` (linkat through /proc), so no
/// other name ever exists. Where that is impossible (no O_TMPFILE on the file system, /proc
/// not mounted), a hidden temporary `.<name>.partial-<pid>-<n>` is written and renamed onto
/// `path`; a kill can leave that temporary behind, never a partial `path`, and the next
/// make_output_folder on the folder removes it. Throws std::runtime_error naming the path.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// The same for a writer that streams its content (e.g. grains::write_ply).
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

}  // namespace rice::experiments
