// Every file a command or a save writes, planned before the work starts (issue 18): each output is
// checked when it is added (its folder exists and takes a new file, it is not a folder, not one of
// the inputs unless overwriting them was asked for, not named twice), by creating its temporary
// file beside it right away. The work then writes each temporary; commit() renames them all only
// once every one is written. A failure anywhere (an exception, a failed rename) removes the
// temporaries and leaves none of the outputs behind: files that existed are put back as they were.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace stratamesh {

class OutputPlan {
public:
    // inputs: the files the work reads (empty names ignored). overwrite: an output may replace one.
    explicit OutputPlan(std::vector<std::string> inputs = {}, bool overwrite = false);
    ~OutputPlan(); // removes every temporary file that commit() did not rename
    OutputPlan(const OutputPlan &) = delete;
    OutputPlan &operator=(const OutputPlan &) = delete;

    // Plans `path`, described by `role` ("model", "report", ...) in messages. Throws FileError
    // naming the path when it is empty, a folder, in a folder that is missing or not writable,
    // already planned, or an input (without overwrite).
    void add(const std::string &path, const std::string &role);

    // Writes the planned `path` through its temporary file, which keeps the extension (libraries
    // choose the format from it): write(temporaryPath) for writers that take a file name,
    // writeText(stream) for text. Throws FileError for a path never added.
    void write(const std::string &path, const std::function<void(const std::string &)> &write);
    void writeText(const std::string &path, const std::function<void(std::ostream &)> &write);

    // Drops a planned output the work turned out not to produce (a TetGen run that failed has no
    // mesh, but its report is still written): its temporary is removed, the target left alone.
    void discard(const std::string &path);

    // Renames every temporary over its target. Throws FileError when an output was never written
    // or a rename fails; then the outputs already renamed are undone.
    void commit();

    // The planned outputs, in the order they were added.
    std::vector<std::string> paths() const;

private:
    struct Output;
    Output &find(const std::string &path);
    std::vector<std::string> m_inputs;
    bool m_overwrite = false;
    bool m_committed = false;
    std::vector<std::unique_ptr<Output>> m_outputs;
};

// True when a and b name the same file: the same inode when both exist, else the same absolute,
// normalised path.
bool sameFile(const std::string &a, const std::string &b);

} // namespace stratamesh
