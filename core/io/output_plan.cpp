#include "io/output_plan.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/file_mode.h"

#include <cerrno>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace stratamesh {

namespace {

std::string folderOf(const std::string &path)
{
    const std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? std::string("/") : path.substr(0, slash);
}

} // namespace

bool sameFile(const std::string &a, const std::string &b)
{
    struct stat sa {
    }, sb{};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    std::error_code ea, eb;
    const std::filesystem::path pa = std::filesystem::weakly_canonical(a, ea);
    const std::filesystem::path pb = std::filesystem::weakly_canonical(b, eb);
    if (ea || eb)
        return std::filesystem::absolute(a).lexically_normal()
               == std::filesystem::absolute(b).lexically_normal();
    return pa == pb;
}

struct OutputPlan::Output {
    std::string path;
    std::string role;
    std::string temporary; // empty once renamed or removed
    std::string backup;    // a hard link to the file it replaced, while commit() runs
    bool written = false;
    bool existed = false;
};

OutputPlan::OutputPlan(std::vector<std::string> inputs, bool overwrite)
    : m_inputs(std::move(inputs)), m_overwrite(overwrite)
{
}

OutputPlan::~OutputPlan()
{
    for (const auto &o : m_outputs)
        if (!o->temporary.empty())
            ::unlink(o->temporary.c_str());
}

void OutputPlan::add(const std::string &path, const std::string &role)
{
    if (m_committed)
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "internal error: output planned after the commit"));
    if (path.empty())
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "no file name given for the %1"),
                        {role}});
    struct stat st {};
    const bool exists = ::stat(path.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode))
        throw FileError(path, 0,
                        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "cannot write the %1: it is a folder"),
                                    {role}});
    for (const std::string &input : m_inputs)
        if (!m_overwrite && !input.empty() && sameFile(path, input))
            throw FileError(
                path, 0,
                MessageText{
                    QT_TRANSLATE_NOOP(
                        "stratamesh::Core",
                        "the %1 would replace the input file %2: choose another file, or ask to "
                        "overwrite it (stratamesh-cli: --overwrite); nothing was written"),
                    {role, input}});
    for (const auto &o : m_outputs)
        if (sameFile(path, o->path))
            throw FileError(path, 0,
                            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                          "named twice: as the %1 and as the %2"),
                                        {o->role, role}});
    const std::string dir = folderOf(path);
    struct stat ds {};
    if (::stat(dir.c_str(), &ds) != 0)
        throw FileError(
            path, 0,
            MessageText{
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "cannot write the %1: its folder %2 does not exist (nothing was written)"),
                {role, dir}});
    if (!S_ISDIR(ds.st_mode))
        throw FileError(
            path, 0,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "cannot write the %1: %2 is not a folder (nothing was written)"),
                {role, dir}});
    // The temporary file is the writability check: whatever a permission test would say (root,
    // ACLs, read-only mounts), creating a file in the folder is what the work will need.
    const std::size_t slash = path.find_last_of('/');
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::size_t dot = base.find_last_of('.');
    const std::string ext = dot == std::string::npos || dot == 0 ? std::string() : base.substr(dot);
    const std::string prefix =
        slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
    std::string pattern = prefix + "." + base + ".XXXXXX" + ext;
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = ::mkstemps(name.data(), static_cast<int>(ext.size()));
    if (fd < 0) {
        const int error = errno;
        throw FileError(
            path, 0,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "cannot write the %1 in folder %2: %3 (nothing was written)"),
                {role, dir, systemError(error)}});
    }
    // mkstemps gives 0600; give the file the mode a plain open() would (or the replaced file's).
    (void)::fchmod(fd, exists ? (st.st_mode & 07777) : (0666 & ~currentUmask()));
    ::close(fd);
    auto output = std::make_unique<Output>();
    output->path = path;
    output->role = role;
    output->temporary = name.data();
    output->existed = exists;
    m_outputs.push_back(std::move(output));
}

OutputPlan::Output &OutputPlan::find(const std::string &path)
{
    for (const auto &o : m_outputs)
        if (o->path == path)
            return *o;
    throw FileError(
        path, 0,
        QT_TRANSLATE_NOOP("stratamesh::Core",
                          "internal error: this output was not planned before the work"));
}

void OutputPlan::write(const std::string &path,
                       const std::function<void(const std::string &)> &write)
{
    Output &o = find(path);
    if (o.temporary.empty())
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "internal error: output written after the commit"));
    write(o.temporary);
    o.written = true;
}

void OutputPlan::writeText(const std::string &path,
                           const std::function<void(std::ostream &)> &write)
{
    this->write(path, [&](const std::string &temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            throw FileError(
                path, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write the %1"),
                            {find(path).role}});
        write(out);
        out.flush();
        if (!out)
            throw FileError(
                path, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "cannot write the %1: %2 (nothing was written)"),
                            {find(path).role, systemError(errno)}});
        out.close();
        // Flushed to disk before the rename, so that a crash never shows a short file.
        const int fd = ::open(temporary.c_str(), O_RDONLY);
        if (fd >= 0) {
            const bool synced = ::fsync(fd) == 0;
            const int error = errno;
            ::close(fd);
            if (!synced)
                throw FileError(
                    path, 0,
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "cannot write the %1: %2 (nothing was written)"),
                                {find(path).role, systemError(error)}});
        }
    });
}

void OutputPlan::discard(const std::string &path)
{
    for (auto it = m_outputs.begin(); it != m_outputs.end(); ++it)
        if ((*it)->path == path) {
            if (!(*it)->temporary.empty())
                ::unlink((*it)->temporary.c_str());
            m_outputs.erase(it);
            return;
        }
}

void OutputPlan::commit()
{
    if (m_committed)
        throw FileError(
            m_outputs.empty() ? std::string() : m_outputs.front()->path, 0,
            QT_TRANSLATE_NOOP("stratamesh::Core", "internal error: outputs committed twice"));
    for (const auto &o : m_outputs)
        if (!o->written)
            throw FileError(
                o->path, 0,
                MessageText{QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "internal error: the %1 was never written (nothing was written)"),
                            {o->role}});
    std::size_t done = 0;
    std::string failure; // the system's reason
    for (; done < m_outputs.size(); ++done) {
        Output &o = *m_outputs[done];
        // A replaced file is kept under a second name until every rename succeeded.
        if (o.existed) {
            const std::string backup = o.temporary + ".previous";
            if (::link(o.path.c_str(), backup.c_str()) == 0)
                o.backup = backup;
        }
        if (::rename(o.temporary.c_str(), o.path.c_str()) != 0) {
            failure = systemError(errno);
            break;
        }
        o.temporary.clear();
    }
    if (done < m_outputs.size()) {
        // Undo: outputs already renamed are removed, or put back as they were.
        for (std::size_t i = 0; i < done; ++i) {
            Output &o = *m_outputs[i];
            if (!o.backup.empty())
                (void)::rename(o.backup.c_str(), o.path.c_str());
            else if (!o.existed)
                (void)::unlink(o.path.c_str());
        }
        if (!m_outputs[done]->backup.empty())
            (void)::unlink(m_outputs[done]->backup.c_str());
        throw FileError(
            m_outputs[done]->path, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "cannot replace the file: %1 (no output was written)"),
                        {failure}});
    }
    m_committed = true;
    for (const auto &o : m_outputs)
        if (!o->backup.empty())
            (void)::unlink(o->backup.c_str());
    // Make the renames durable; a failure here leaves complete files, so it is not an error.
    for (const auto &o : m_outputs) {
        const int dirFd = ::open(folderOf(o->path).c_str(), O_RDONLY | O_DIRECTORY);
        if (dirFd >= 0) {
            (void)::fsync(dirFd);
            ::close(dirFd);
        }
    }
}

std::vector<std::string> OutputPlan::paths() const
{
    std::vector<std::string> p;
    for (const auto &o : m_outputs)
        p.push_back(o->path);
    return p;
}

} // namespace stratamesh
