// Typed errors that say where: a file and line, or an entity and a position.
#pragma once

#include <stdexcept>
#include <string>

namespace stratamesh {

// A problem in an input file; the message always reads "FILE:LINE: cause".
class FileError : public std::runtime_error {
public:
    FileError(std::string file, int line, std::string cause)
        : std::runtime_error(format(file, line, cause)), m_file(std::move(file)), m_line(line),
          m_cause(std::move(cause))
    {
    }
    const std::string &file() const { return m_file; }
    int line() const { return m_line; }
    const std::string &cause() const { return m_cause; }

private:
    static std::string format(const std::string &file, int line, const std::string &cause)
    {
        return line > 0 ? file + ":" + std::to_string(line) + ": " + cause : file + ": " + cause;
    }
    std::string m_file;
    int m_line = 0;
    std::string m_cause;
};

// A precondition of an algorithm that the input does not meet (empty model, NaN, ...).
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Raised by Progress::tick() when the user asked to stop; unwinds without a partial result.
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled by the user") {}
};

} // namespace stratamesh
