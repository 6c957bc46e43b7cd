// Every file StrataMesh writes goes to a temporary file beside the target and is renamed over it
// only once complete and synced: a failed or interrupted write never leaves a partial file, and an
// existing file survives intact.
#pragma once

#include "common/message_text.h"

#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace stratamesh {

class AtomicFile {
public:
    // Creates the temporary file now (".<name>.XXXXXX<ext>" in the target's folder, keeping the
    // extension because libraries choose the format from it). Throws FileError when the folder is
    // missing or not writable, or when the target is a folder.
    explicit AtomicFile(std::string path);
    ~AtomicFile(); // removes the temporary file unless commit() succeeded
    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &operator=(const AtomicFile &) = delete;

    const std::string &path() const { return m_path; }
    const std::string &temporaryPath() const { return m_temporary; }

    // Buffered writes into the temporary file. Errors (full disk, quota, file size limit) are
    // remembered and reported by commit(); writing stops at the first one.
    std::ostream &stream();

    // Flushes, syncs and renames over the target. Throws FileError naming the target and the
    // system's cause ("No space left on device") after removing the temporary file.
    // Libraries that write by file name may write temporaryPath() themselves, then commit().
    void commit();

private:
    // The pattern ends with " (nothing was written)".
    [[noreturn]] void fail(const MessageText &cause);

    class Buffer;
    std::string m_path;
    std::string m_temporary;
    int m_fd = -1;
    bool m_committed = false;
    std::unique_ptr<Buffer> m_buffer;
    std::unique_ptr<std::ostream> m_stream;
};

// Writes through a stream: write(out) then commit.
void writeTextFileAtomically(const std::string &path,
                             const std::function<void(std::ostream &)> &write);
// For libraries that write by file name: write(temporaryPath) then commit. write throws on failure.
void writeFileAtomically(const std::string &path,
                         const std::function<void(const std::string &)> &write);

} // namespace stratamesh
