// Typed errors that say where: a file and line, or an entity and a position.
#pragma once

#include "common/message_text.h"

#include <stdexcept>
#include <string>

namespace stratamesh {

// A problem in an input file; the message always reads "FILE:LINE: cause". Built from a
// MessageText, the cause is its English text and text() keeps the pattern and values so the GUI
// can show the sentence in the user's language; built from a plain string, text() has no pattern.
class FileError : public std::runtime_error {
public:
    FileError(std::string file, int line, std::string cause)
        : std::runtime_error(format(file, line, cause)), m_file(std::move(file)), m_line(line),
          m_cause(std::move(cause))
    {
    }
    FileError(std::string file, int line, MessageText cause)
        : FileError(std::move(file), line, cause.text())
    {
        m_text = std::move(cause);
    }
    // Overload resolution: a string literal is a plain cause, not a pattern.
    FileError(std::string file, int line, const char *cause)
        : FileError(std::move(file), line, std::string(cause))
    {
    }
    const std::string &file() const { return m_file; }
    int line() const { return m_line; }
    const std::string &cause() const { return m_cause; }
    const MessageText &text() const { return m_text; }

private:
    static std::string format(const std::string &file, int line, const std::string &cause)
    {
        return line > 0 ? file + ":" + std::to_string(line) + ": " + cause : file + ": " + cause;
    }
    std::string m_file;
    int m_line = 0;
    std::string m_cause;
    MessageText m_text;
};

// A precondition of an algorithm that the input does not meet (empty model, NaN, ...).
// Built from a MessageText, what() is its English text and text() keeps the pattern and values.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    explicit InputError(MessageText cause)
        : std::runtime_error(cause.text()), m_text(std::move(cause))
    {
    }
    const MessageText &text() const { return m_text; }

private:
    MessageText m_text;
};

// The cause an InputError gives to a FileError that reports it in a file: its pattern and values,
// or its English text as a pattern without values.
inline MessageText causeOf(const InputError &e)
{
    return e.text().pattern.empty() ? MessageText{e.what(), {}} : e.text();
}

// Raised by Progress::tick() when the user asked to stop; unwinds without a partial result.
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled by the user") {}
};

} // namespace stratamesh
