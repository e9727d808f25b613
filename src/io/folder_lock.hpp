// One writer per output folder: an flock(2) on DIR/.tumble.lock, held while a
// render, resume or assemble changes the folder. The kernel drops the lock when
// its holder exits, however it exits, so a lock left by kill -9 is simply free
// again. The file stays (removing a locked file races with the next locker)
// and names its last holder, for the message of whoever is refused. A folder
// that will be refused (a foreign one) gets no lock file: its users check it
// first, then lock (refuse_if_held), then check again under the lock.
//
// Deciding is atomic: every taker and every prober first holds the folder's
// gate, an flock on the folder itself, for the few calls that decide (no
// waiting on anything else inside). So a shard that finds the lock free,
// writes its note and turns its exclusive lock into a shared one cannot be
// seen half-way by another shard starting at the same moment, which would
// take the transient exclusive lock for a foreign render and be refused.
#pragma once

#include <filesystem>
#include <string>

namespace tumble::io {

/// The lock file's name inside an output folder.
inline constexpr const char* kLockFileName = ".tumble.lock";


class FolderLock {
 public:
  /// How the folder is held. `exclusive`: a whole render, a resume, assemble.
  /// `shared`: a shard (--frames A:B), which runs beside the other shards of
  /// the same render (`key` equal) and never beside anything else.
  enum class Mode { exclusive, shared };

  /// Takes the lock or throws InputError "output folder DIR is in use by
  /// <holder>; ...". `holder` describes this process for the next one refused
  /// ("tumble render scene.toml"); `key` tells shards of one render apart from others.
  FolderLock(const std::filesystem::path& dir, Mode mode, const std::string& holder, const std::string& key);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  /// Who holds the folder now: nobody, or the shards of the render `key`.
  enum class Holder { none, siblings };
  /// For a folder about to be refused: throws the "in use by <holder>"
  /// InputError when its lock is held now (a folder mid-way through another
  /// render can look foreign), except by shards of the render `sibling_key`
  /// (non-empty: the caller is such a shard, which may go on, lock and check
  /// again). Creates and writes nothing.
  static Holder refuse_if_held(const std::filesystem::path& dir, const std::string& sibling_key = "");
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace tumble::io
