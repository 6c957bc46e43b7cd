// Zip archives through minizip (Debian libminizip-dev): the container of RINGMesh .gm files.
// Entries are read whole into memory, in chunks, so a lying size in the zip directory cannot
// make us allocate more than the entry really decompresses to.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace stratamesh {

class ZipReader {
public:
    // Throws FileError(path, cause) when the file is missing or not a zip archive.
    explicit ZipReader(std::string path);
    ~ZipReader();
    ZipReader(const ZipReader &) = delete;
    ZipReader &operator=(const ZipReader &) = delete;

    const std::string &path() const { return m_path; }
    // Entry names in archive order.
    const std::vector<std::string> &names() const { return m_names; }
    bool contains(const std::string &name) const;
    // The entry's bytes. Throws FileError("archive:entry", cause) when it is missing, fails to
    // decompress, fails its CRC or exceeds maxBytes.
    std::string read(const std::string &name, std::size_t maxBytes = std::size_t(1) << 32) const;

private:
    std::string m_path;
    void *m_zip = nullptr;
    std::vector<std::string> m_names;
};

// Writes entries (deflated, with a fixed date so equal content gives equal archives) to `path`
// directly: callers wanting an atomic write pass AtomicFile::temporaryPath().
class ZipWriter {
public:
    explicit ZipWriter(std::string path); // throws FileError
    ~ZipWriter();                         // closes without throwing if close() was not called
    ZipWriter(const ZipWriter &) = delete;
    ZipWriter &operator=(const ZipWriter &) = delete;

    void add(const std::string &name, const std::string &bytes); // throws FileError
    void close();                                                // throws FileError

private:
    std::string m_path;
    void *m_zip = nullptr;
};

} // namespace stratamesh
