// One writer per output folder: an flock(2) on DIR/.tumble.lock, held while a
// render, resume or assemble changes the folder. The kernel drops the lock when
// its holder exits, however it exits, so a lock left by kill -9 is simply free
// again. The file stays (removing a locked file races with the next locker)
// and names its last holder, for the message of whoever is refused.
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
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace tumble::io
