#include "io/geogram_file.h"

#include "common/error.h"
#include "common/translate_noop.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>

namespace stratamesh {

namespace {

// A GeoFile counts items with 32 bits: anything larger is not one (and may be a zip bomb).
constexpr std::size_t kMaxInflated = std::size_t(1) << 32;

// Reads little-endian fields within [pos, end); every read is checked against end first.
class ByteCursor {
public:
    ByteCursor(const std::string &bytes, const std::string &where)
        : m_bytes(bytes), m_where(where), m_end(bytes.size())
    {
    }

    std::size_t pos() const { return m_pos; }
    std::size_t left() const { return m_end - m_pos; }
    void setEnd(std::size_t end) { m_end = end; }
    void seek(std::size_t pos) { m_pos = pos; }

    // The pattern ends with " at byte %N", N one more than its values: the position fills it.
    [[noreturn]] void fail(MessageText cause) const
    {
        cause.args.push_back(std::to_string(m_pos));
        throw FileError(m_where, 0, cause);
    }

    void need(std::uint64_t n, const char *what) const
    {
        if (n > left())
            fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                               "%1 needs %2 bytes but only %3 are left at byte %4"),
                             {std::string(what), std::to_string(n), std::to_string(left())}});
    }

    std::uint32_t u32(const char *what)
    {
        need(4, what);
        std::uint32_t v;
        std::memcpy(&v, m_bytes.data() + m_pos, 4);
        m_pos += 4;
        return v;
    }

    std::uint64_t u64(const char *what)
    {
        need(8, what);
        std::uint64_t v;
        std::memcpy(&v, m_bytes.data() + m_pos, 8);
        m_pos += 8;
        return v;
    }

    std::string bytes(std::uint64_t n, const char *what)
    {
        need(n, what);
        std::string s = m_bytes.substr(m_pos, std::size_t(n));
        m_pos += std::size_t(n);
        return s;
    }

    std::string str(const char *what) { return bytes(u32(what), what); }

private:
    const std::string &m_bytes;
    const std::string &m_where;
    std::size_t m_pos = 0;
    std::size_t m_end;
};

std::string zlibCause(const char *action, int code, const z_stream &z)
{
    return std::string(action)
           + " failed: " + (z.msg ? z.msg : "zlib error " + std::to_string(code));
}

class Parser {
public:
    Parser(const std::string &raw, const std::string &where) : c(raw, where) {}

    GeogramFile run()
    {
        const std::string head = chunkHeader();
        if (head != "HEAD")
            c.fail(MessageText{
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "not a Geogram file (first chunk is '%1', expected 'HEAD') at byte %2"),
                {printable(head)}});
        const std::string magic = c.str("HEAD magic");
        if (magic == "GEOGRAM-GARGANTUA")
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "64-bit (GARGANTUA) Geogram files are not supported at byte %1"),
                {}});
        if (magic != "GEOGRAM")
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "not a Geogram file (magic '%1') at byte %2"),
                {printable(magic)}});
        c.str("HEAD version");
        endChunk("HEAD");
        while (c.pos() < m_total) {
            const std::string cls = chunkHeader();
            if (cls == "ATTS")
                attributeSet();
            else if (cls == "ATTR")
                attribute();
            else if (cls == "CMNT")
                m_file.comments.push_back(c.str("CMNT comment"));
            else if (cls == "CMDL")
                commandLine();
            else if (cls == "SPTR")
                break; // a second mesh follows; RINGMesh stores one per file
            else
                c.seek(m_chunkEnd); // unknown chunk: its size was checked, skip it
            endChunk(cls);
        }
        return std::move(m_file);
    }

private:
    static std::string printable(const std::string &s)
    {
        std::string out;
        for (unsigned char ch : s)
            out += (ch >= 32 && ch < 127) ? char(ch) : '?';
        return out;
    }

    std::string chunkHeader()
    {
        c.setEnd(m_total);
        const std::string cls = c.bytes(4, "chunk class");
        const std::uint64_t size = c.u64("chunk size");
        if (size > c.left())
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "chunk '%1' claims %2 bytes but only %3 are left at byte %4"),
                {printable(cls), std::to_string(size), std::to_string(c.left())}});
        m_chunkEnd = c.pos() + std::size_t(size);
        c.setEnd(m_chunkEnd); // reads inside the chunk cannot run past it
        return cls;
    }

    void endChunk(const std::string &cls)
    {
        if (c.pos() != m_chunkEnd)
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "chunk '%1' has %2 bytes more than its fields at byte %3"),
                {printable(cls), std::to_string(m_chunkEnd - c.pos())}});
    }

    void attributeSet()
    {
        GeogramAttributeSet set;
        set.name = c.str("ATTS name");
        set.items = c.u32("ATTS item count");
        if (m_file.findSet(set.name))
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                 "attribute set '%1' is defined twice at byte %2"),
                               {set.name}});
        m_file.sets.push_back(std::move(set));
    }

    void attribute()
    {
        GeogramAttribute a;
        a.set = c.str("ATTR set name");
        a.name = c.str("ATTR name");
        a.elementType = c.str("ATTR element type");
        a.elementSize = c.u32("ATTR element size");
        a.dimension = c.u32("ATTR dimension");
        const GeogramAttributeSet *set = m_file.findSet(a.set);
        if (!set)
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "attribute '%1' belongs to the undefined set '%2' at byte %3"),
                {a.name, a.set}});
        if (m_file.find(a.set, a.name))
            c.fail(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "attribute '%1' of set '%2' is defined twice at byte %3"),
                {a.name, a.set}});
        // Each factor is below 2^32, so the product of the first two fits; the third is checked.
        const std::uint64_t perItem = std::uint64_t(a.elementSize) * a.dimension;
        if (set->items != 0 && perItem > c.left() / set->items)
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                 "attribute '%1' of %2 items × %3 bytes is larger "
                                                 "than its chunk (%4 bytes left) at byte %5"),
                               {a.name, std::to_string(set->items), std::to_string(perItem),
                                std::to_string(c.left())}});
        const std::uint64_t size = perItem * set->items;
        if (size != c.left())
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                 "attribute '%1' should hold %2 bytes (%3 items of "
                                                 "'%4') but its chunk holds %5 at byte %6"),
                               {a.name, std::to_string(size), std::to_string(set->items), a.set,
                                std::to_string(c.left())}});
        a.data = c.bytes(size, "ATTR data");
        m_file.attributes.push_back(std::move(a));
    }

    void commandLine()
    {
        const std::uint32_t n = c.u32("CMDL count");
        if (n > c.left() / 4) // every string takes at least its 4-byte length
            c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                 "CMDL claims %1 strings in %2 bytes at byte %3"),
                               {std::to_string(n), std::to_string(c.left())}});
        for (std::uint32_t i = 0; i < n; ++i)
            m_file.commandLine.push_back(c.str("CMDL string"));
    }

    ByteCursor c;
    std::size_t m_total = c.left();
    std::size_t m_chunkEnd = 0;
    GeogramFile m_file;
};

void putU32(std::string &out, std::uint32_t v)
{
    char b[4];
    std::memcpy(b, &v, 4);
    out.append(b, 4);
}

void putU64(std::string &out, std::uint64_t v)
{
    char b[8];
    std::memcpy(b, &v, 8);
    out.append(b, 8);
}

void putString(std::string &out, const std::string &s)
{
    putU32(out, std::uint32_t(s.size()));
    out += s;
}

void putChunk(std::string &out, const char *cls, const std::string &body)
{
    out.append(cls, 4);
    putU64(out, body.size());
    out += body;
}

template <typename T>
std::vector<T> typedValues(const GeogramAttribute &a, const char *type, const std::string &where)
{
    if (a.elementSize != sizeof(T))
        throw FileError(
            where, 0,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "attribute '%1' has elements of %2 bytes, expected %3 (%4)"),
                {a.name, std::to_string(a.elementSize), type, std::to_string(sizeof(T))}});
    std::vector<T> v(a.data.size() / sizeof(T));
    std::memcpy(v.data(), a.data.data(), v.size() * sizeof(T));
    return v;
}

template <typename T>
GeogramAttribute makeAttribute(std::string set, std::string name, const char *type,
                               const std::vector<T> &values, std::uint32_t dimension)
{
    GeogramAttribute a;
    a.set = std::move(set);
    a.name = std::move(name);
    a.elementType = type;
    a.elementSize = sizeof(T);
    a.dimension = dimension;
    a.data.assign(reinterpret_cast<const char *>(values.data()), values.size() * sizeof(T));
    return a;
}

} // namespace

const GeogramAttributeSet *GeogramFile::findSet(const std::string &name) const
{
    const auto it =
        std::find_if(sets.begin(), sets.end(), [&](const auto &s) { return s.name == name; });
    return it == sets.end() ? nullptr : &*it;
}

const GeogramAttribute *GeogramFile::find(const std::string &set, const std::string &name) const
{
    const auto it = std::find_if(attributes.begin(), attributes.end(),
                                 [&](const auto &a) { return a.set == set && a.name == name; });
    return it == attributes.end() ? nullptr : &*it;
}

std::string gunzip(const std::string &compressed, const std::string &where)
{
    z_stream z{};
    if (inflateInit2(&z, 15 + 16) != Z_OK) // 15 + 16: a gzip header is expected, not raw zlib
        throw FileError(where, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot initialise zlib"));
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(compressed.data()));
    z.avail_in = uInt(compressed.size());
    std::string out;
    char buffer[1 << 16];
    int code = Z_OK;
    while (code != Z_STREAM_END) {
        z.next_out = reinterpret_cast<Bytef *>(buffer);
        z.avail_out = sizeof buffer;
        code = inflate(&z, Z_NO_FLUSH);
        if (code != Z_OK && code != Z_STREAM_END) {
            const std::string cause = code == Z_BUF_ERROR
                                          ? "truncated gzip stream"
                                          : zlibCause("gzip decompression", code, z);
            inflateEnd(&z);
            throw FileError(
                where, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 (after %2 bytes)"),
                            {cause, std::to_string(out.size())}});
        }
        out.append(buffer, sizeof buffer - z.avail_out);
        if (out.size() > kMaxInflated) {
            inflateEnd(&z);
            throw FileError(
                where, 0,
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "decompresses to more than 4 GiB (a GeoFile indexes with 32 bits)"));
        }
    }
    inflateEnd(&z);
    return out;
}

std::string gzip(const std::string &raw, const std::string &where)
{
    z_stream z{};
    if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw FileError(where, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot initialise zlib"));
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(raw.data()));
    z.avail_in = uInt(raw.size());
    std::string out;
    char buffer[1 << 16];
    int code = Z_OK;
    while (code != Z_STREAM_END) {
        z.next_out = reinterpret_cast<Bytef *>(buffer);
        z.avail_out = sizeof buffer;
        code = deflate(&z, Z_FINISH);
        if (code == Z_STREAM_ERROR) {
            deflateEnd(&z);
            throw FileError(where, 0, zlibCause("gzip compression", code, z));
        }
        out.append(buffer, sizeof buffer - z.avail_out);
    }
    deflateEnd(&z);
    return out;
}

GeogramFile parseGeogramFile(const std::string &raw, const std::string &where)
{
    return Parser(raw, where).run();
}

GeogramFile readGeogramFile(const std::string &compressed, const std::string &where)
{
    return parseGeogramFile(gunzip(compressed, where), where);
}

std::string serializeGeogramFile(const GeogramFile &file)
{
    std::string out, body;
    putString(body, "GEOGRAM");
    putString(body, "1.0");
    putChunk(out, "HEAD", body);
    for (const std::string &comment : file.comments) {
        body.clear();
        putString(body, comment);
        putChunk(out, "CMNT", body);
    }
    if (!file.commandLine.empty()) {
        body.clear();
        putU32(body, std::uint32_t(file.commandLine.size()));
        for (const std::string &arg : file.commandLine)
            putString(body, arg);
        putChunk(out, "CMDL", body);
    }
    for (const GeogramAttributeSet &set : file.sets) {
        body.clear();
        putString(body, set.name);
        putU32(body, set.items);
        putChunk(out, "ATTS", body);
        for (const GeogramAttribute &a : file.attributes) {
            if (a.set != set.name)
                continue;
            if (a.data.size() != std::uint64_t(a.elementSize) * a.dimension * set.items)
                throw InputError(MessageText{
                    QT_TRANSLATE_NOOP(
                        "stratamesh::Core",
                        "Geogram attribute '%1' holds %2 bytes, not %3 items of its set '%4'"),
                    {a.name, std::to_string(a.data.size()), std::to_string(set.items), a.set}});
            body.clear();
            putString(body, a.set);
            putString(body, a.name);
            putString(body, a.elementType);
            putU32(body, a.elementSize);
            putU32(body, a.dimension);
            body += a.data;
            putChunk(out, "ATTR", body);
        }
    }
    return out;
}

std::string writeGeogramFile(const GeogramFile &file, const std::string &where)
{
    return gzip(serializeGeogramFile(file), where);
}

std::vector<double> geogramDoubles(const GeogramAttribute &a, const std::string &where)
{
    return typedValues<double>(a, "double", where);
}

std::vector<std::uint32_t> geogramIndices(const GeogramAttribute &a, const std::string &where)
{
    return typedValues<std::uint32_t>(a, "index_t", where);
}

GeogramAttribute geogramAttribute(std::string set, std::string name,
                                  const std::vector<double> &values, std::uint32_t dimension)
{
    return makeAttribute(std::move(set), std::move(name), "double", values, dimension);
}

GeogramAttribute geogramAttribute(std::string set, std::string name,
                                  const std::vector<std::uint32_t> &values, std::uint32_t dimension)
{
    return makeAttribute(std::move(set), std::move(name), "index_t", values, dimension);
}

} // namespace stratamesh
