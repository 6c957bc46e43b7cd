// A sentence for the user kept as an English pattern with %1…%9 places and the values that fill
// them. Core builds it and reports print text(); the GUI translates the pattern (lupdate reads the
// patterns from core, marked QT_TRANSLATE_NOOP in context kCoreTextContext) and fills the same
// values, so ledger notes and validity problems read in the user's language.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace stratamesh {

inline constexpr const char *kCoreTextContext = "stratamesh::Core";

struct MessageText {
    MessageText() = default;
    // Not explicit: a reader writes {pattern, {values}} or {pattern, {values}, {parts}}.
    MessageText(std::string pattern_, std::vector<std::string> args_ = {},
                std::vector<MessageText> parts_ = {})
        : pattern(std::move(pattern_)), args(std::move(args_)), parts(std::move(parts_))
    {
    }

    std::string pattern;
    std::vector<std::string> args;
    // Sentences filling the places after the values (%(args.size() + 1)…), each translated on its
    // own: "facet %1: %2" with the coordinate's problem as %2.
    std::vector<MessageText> parts;

    std::string text() const
    {
        if (parts.empty())
            return fillPattern(pattern, args);
        std::vector<std::string> values = args;
        for (const MessageText &part : parts)
            values.push_back(part.text());
        return fillPattern(pattern, values);
    }

    // %N (N = 1…9) becomes args[N − 1]; a % not followed by a digit with a value stays.
    static std::string fillPattern(const std::string &pattern, const std::vector<std::string> &args)
    {
        std::string out;
        out.reserve(pattern.size() + 16 * args.size());
        for (std::size_t i = 0; i < pattern.size(); ++i) {
            const char c = pattern[i];
            if (c == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' && pattern[i + 1] <= '9'
                && std::size_t(pattern[i + 1] - '1') < args.size()) {
                out += args[std::size_t(pattern[i + 1] - '1')];
                ++i;
            } else {
                out += c;
            }
        }
        return out;
    }
};

} // namespace stratamesh
