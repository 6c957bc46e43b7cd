#include "io/zip_archive.h"

#include "common/error.h"
#include "common/translate_noop.h"

#include <unzip.h>
#include <zip.h>

#include <algorithm>

namespace stratamesh {

namespace {

std::string unzipCause(int code)
{
    switch (code) {
    case UNZ_CRCERROR:
        return "CRC mismatch (corrupt archive)";
    case UNZ_BADZIPFILE:
        return "corrupt zip data";
    case UNZ_ERRNO:
        return "read error";
    case UNZ_INTERNALERROR:
        return "internal zip error";
    case UNZ_PARAMERROR:
        return "bad zip parameter";
    case Z_DATA_ERROR:
        return "corrupt compressed data";
    case Z_MEM_ERROR:
        return "out of memory";
    default:
        return "zip error " + std::to_string(code);
    }
}

} // namespace

ZipReader::ZipReader(std::string path) : m_path(std::move(path))
{
    m_zip = unzOpen64(m_path.c_str());
    if (!m_zip)
        throw FileError(
            m_path, 0,
            QT_TRANSLATE_NOOP(
                "stratamesh::Core",
                "not a readable zip archive (missing file, or no zip central directory)"));
    char name[4096];
    for (int code = unzGoToFirstFile(m_zip); code != UNZ_END_OF_LIST_OF_FILE;
         code = unzGoToNextFile(m_zip)) {
        unz_file_info64 info;
        if (code == UNZ_OK)
            code = unzGetCurrentFileInfo64(m_zip, &info, name, sizeof name, nullptr, 0, nullptr, 0);
        if (code != UNZ_OK) {
            unzClose(m_zip);
            m_zip = nullptr;
            throw FileError(
                m_path, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "corrupt zip directory after %1 entries: %2"),
                            {std::to_string(m_names.size()), unzipCause(code)}});
        }
        m_names.emplace_back(name);
    }
}

ZipReader::~ZipReader()
{
    if (m_zip)
        unzClose(m_zip);
}

bool ZipReader::contains(const std::string &name) const
{
    return std::find(m_names.begin(), m_names.end(), name) != m_names.end();
}

std::string ZipReader::read(const std::string &name, std::size_t maxBytes) const
{
    const std::string where = m_path + ":" + name;
    if (!contains(name))
        throw FileError(where, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "entry missing from the archive"));
    if (unzLocateFile(m_zip, name.c_str(), 1) != UNZ_OK)
        throw FileError(
            where, 0,
            QT_TRANSLATE_NOOP("stratamesh::Core", "entry cannot be located in the archive"));
    int code = unzOpenCurrentFile(m_zip);
    if (code != UNZ_OK)
        throw FileError(
            where, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "cannot open the entry: %1"),
                        {unzipCause(code)}});
    std::string out;
    char buffer[1 << 16];
    for (;;) {
        const int n = unzReadCurrentFile(m_zip, buffer, sizeof buffer);
        if (n < 0) {
            unzCloseCurrentFile(m_zip);
            throw FileError(
                where, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "cannot decompress the entry after %1 bytes: %2"),
                            {std::to_string(out.size()), unzipCause(n)}});
        }
        if (n == 0)
            break;
        out.append(buffer, std::size_t(n));
        if (out.size() > maxBytes) {
            unzCloseCurrentFile(m_zip);
            throw FileError(
                where, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "entry larger than %1 bytes"),
                            {std::to_string(maxBytes)}});
        }
    }
    code = unzCloseCurrentFile(m_zip); // reports a CRC mismatch once the entry is read whole
    if (code != UNZ_OK)
        throw FileError(where, 0, unzipCause(code));
    return out;
}

ZipWriter::ZipWriter(std::string path) : m_path(std::move(path))
{
    m_zip = zipOpen64(m_path.c_str(), APPEND_STATUS_CREATE);
    if (!m_zip)
        throw FileError(m_path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "cannot create the zip archive"));
}

ZipWriter::~ZipWriter()
{
    if (m_zip)
        zipClose(m_zip, nullptr);
}

void ZipWriter::add(const std::string &name, const std::string &bytes)
{
    zip_fileinfo info{};
    info.tmz_date.tm_year = 1980; // the earliest zip date: reproducible archives
    info.tmz_date.tm_mday = 1;
    const int zip64 = bytes.size() >= 0xffffffffu ? 1 : 0;
    if (zipOpenNewFileInZip64(m_zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr,
                              Z_DEFLATED, Z_DEFAULT_COMPRESSION, zip64)
        != ZIP_OK)
        throw FileError(
            m_path + ":" + name, 0,
            QT_TRANSLATE_NOOP("stratamesh::Core", "cannot add the entry to the zip archive"));
    std::size_t done = 0;
    while (done < bytes.size()) {
        const unsigned n = unsigned(std::min<std::size_t>(bytes.size() - done, 1u << 30));
        if (zipWriteInFileInZip(m_zip, bytes.data() + done, n) != ZIP_OK) {
            zipCloseFileInZip(m_zip);
            throw FileError(
                m_path + ":" + name, 0,
                QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write the entry (disk full?)"));
        }
        done += n;
    }
    if (zipCloseFileInZip(m_zip) != ZIP_OK)
        throw FileError(m_path + ":" + name, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "cannot finish the entry"));
}

void ZipWriter::close()
{
    void *zip = m_zip;
    m_zip = nullptr;
    if (zipClose(zip, nullptr) != ZIP_OK)
        throw FileError(
            m_path, 0,
            QT_TRANSLATE_NOOP("stratamesh::Core", "cannot finish the zip archive (disk full?)"));
}

} // namespace stratamesh
