#include "io/atomic_file.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/file_mode.h"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace stratamesh {

// A streambuf over a file descriptor that remembers the first write error instead of throwing.
class AtomicFile::Buffer : public std::streambuf {
public:
    explicit Buffer(int fd) : m_fd(fd), m_data(1 << 16)
    {
        setp(m_data.data(), m_data.data() + m_data.size());
    }
    int error() const { return m_error; }
    bool flushAll() { return drain() && m_error == 0; }

protected:
    int_type overflow(int_type ch) override
    {
        if (!drain())
            return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain()
    {
        if (m_error)
            return false;
        const char *p = pbase();
        std::size_t left = static_cast<std::size_t>(pptr() - pbase());
        while (left > 0) {
            const ssize_t n = ::write(m_fd, p, left);
            if (n < 0) {
                if (errno == EINTR)
                    continue;
                m_error = errno;
                return false;
            }
            p += n;
            left -= static_cast<std::size_t>(n);
        }
        setp(m_data.data(), m_data.data() + m_data.size());
        return true;
    }
    int m_fd;
    int m_error = 0;
    std::vector<char> m_data;
};

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path))
{
    if (m_path.empty())
        throw FileError(m_path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "no file name given"));
    struct stat st {};
    if (::stat(m_path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw FileError(m_path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write: it is a folder"));
    const std::size_t slash = m_path.find_last_of('/');
    const std::string dir =
        slash == std::string::npos ? std::string(".") : m_path.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? m_path : m_path.substr(slash + 1);
    const std::size_t dot = base.find_last_of('.');
    const std::string ext = dot == std::string::npos || dot == 0 ? std::string() : base.substr(dot);
    std::string pattern =
        (slash == std::string::npos ? std::string() : dir) + "." + base + ".XXXXXX" + ext;
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    m_fd = ::mkstemps(name.data(), static_cast<int>(ext.size()));
    if (m_fd < 0) {
        const int error = errno;
        throw FileError(m_path, 0,
                        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "cannot create a file in folder %1: %2"),
                                    {dir, systemError(error)}});
    }
    m_temporary = name.data();
    // mkstemps gives 0600; give the file the mode a plain open() would (or the replaced file's).
    const mode_t mode =
        ::stat(m_path.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~currentUmask());
    (void)::fchmod(m_fd, mode);
}

AtomicFile::~AtomicFile()
{
    if (m_fd >= 0)
        ::close(m_fd);
    if (!m_committed && !m_temporary.empty())
        ::unlink(m_temporary.c_str());
}

std::ostream &AtomicFile::stream()
{
    if (!m_stream) {
        m_buffer = std::make_unique<Buffer>(m_fd);
        m_stream = std::make_unique<std::ostream>(m_buffer.get());
    }
    return *m_stream;
}

void AtomicFile::fail(const MessageText &cause)
{
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
    ::unlink(m_temporary.c_str());
    m_temporary.clear();
    throw FileError(m_path, 0, cause);
}

void AtomicFile::commit()
{
    if (m_committed || m_temporary.empty())
        throw FileError(
            m_path, 0,
            QT_TRANSLATE_NOOP("stratamesh::Core", "internal error: file committed twice"));
    if (m_buffer && !m_buffer->flushAll())
        fail(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write: %1 (nothing was written)"),
            {systemError(m_buffer->error())}});
    // A library may have replaced the file we created: sync whatever now sits at the path.
    const int fd = ::open(m_temporary.c_str(), O_RDONLY);
    if (fd < 0)
        fail(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core",
                              "the temporary file %1 vanished: %2 (nothing was written)"),
            {m_temporary, systemError(errno)}});
    if (::fsync(fd) != 0) {
        const int error = errno;
        ::close(fd);
        fail(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write: %1 (nothing was written)"),
            {systemError(error)}});
    }
    ::close(fd);
    if (::close(m_fd) != 0) {
        const int error = errno;
        m_fd = -1;
        fail(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write: %1 (nothing was written)"),
            {systemError(error)}});
    }
    m_fd = -1;
    if (::rename(m_temporary.c_str(), m_path.c_str()) != 0)
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                           "cannot replace the file: %1 (nothing was written)"),
                         {systemError(errno)}});
    m_committed = true;
    // Make the rename itself durable; a failure here leaves a complete file, so it is not an error.
    const std::size_t slash = m_path.find_last_of('/');
    const std::string dir =
        slash == std::string::npos ? std::string(".") : m_path.substr(0, slash + 1);
    const int dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (dirFd >= 0) {
        (void)::fsync(dirFd);
        ::close(dirFd);
    }
}

void writeTextFileAtomically(const std::string &path,
                             const std::function<void(std::ostream &)> &write)
{
    AtomicFile file(path);
    write(file.stream());
    file.commit();
}

void writeFileAtomically(const std::string &path,
                         const std::function<void(const std::string &)> &write)
{
    AtomicFile file(path);
    write(file.temporaryPath());
    file.commit();
}

} // namespace stratamesh
