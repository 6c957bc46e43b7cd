// One declaration per algorithm parameter: the CLI flags, usage and help, the range checks, the
// GUI form fields, the reports' `parameters` blocks and the README option list are all made from
// these tables (issue 16). Adding a parameter is one entry in its table (e.g. remesh_params.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace stratamesh {

enum class ParamType {
    Int,     // a whole number
    Real,    // a number
    Flag,    // on or off: a CLI flag without value, a check box
    Seed,    // a whole number, the seed of a random sampling
    IntList, // whole numbers, "100,1000" on the command line
};

// How a GUI form scales a field to the model: lengths and volumes follow its size.
enum class ParamScale { None, Length, Volume };

struct ParamInfo {
    std::string key;     // identifier in code and tests: "d_resolution"
    std::string flag;    // command-line option: "--d-resolution"
    std::string jsonKey; // key in the reports' `parameters` block
    ParamType type = ParamType::Real;
    double defaultValue = 0.0;       // of the parameter struct (read from P{}, never repeated)
    std::vector<double> defaultList; // IntList
    double minimum = 0.0, maximum = 0.0;
    bool zeroMeansOff = false; // 0 is accepted below the minimum: off, or derived from another
    std::string unit;          // "m", "s", "MB", "°", "× edge length"; empty for none
    std::string valueName;     // in the usage line: "--sites N"
    std::string label;         // form label with its & shortcut
    std::string help;          // one line: CLI help and GUI tooltip
    std::string thesis;        // where the thesis defines it: "Alg. 4.2, step 4"
    ParamScale scale = ParamScale::None;
    std::string offText;     // what a form shows at 0 when zeroMeansOff ("Off", "None")
    bool jsonString = false; // written as a string in reports (64-bit seeds)
    int decimals = -1;       // of a form's spin box; -1: from the scale or 3
};

// Texts of the tables are English; the GUI translates labels, help and units in this context
// (lupdate reads them from core/params, marked with QT_TRANSLATE_NOOP).
inline constexpr const char *kParamTranslationContext = "stratamesh::Params";

// One parameter of a struct P: its description and how to read and write it.
template <class P>
struct Param {
    ParamInfo info;
    std::function<double(const P &)> get; // numbers; flags as 0 or 1
    std::function<void(P &, double)> set;
    std::function<std::vector<double>(const P &)> getList; // IntList
    std::function<void(P &, const std::vector<double> &)> setList;
};

// The seed entry of a table (key, flag, JSON key, label): `help` says what the seed reproduces.
ParamInfo seedParamInfo(double maximum, const char *help);

// Param of a member `field` of P (int, unsigned, uint64, double or bool).
template <class P, class T>
Param<P> memberParam(T P::*field, ParamInfo info)
{
    Param<P> p;
    p.info = std::move(info);
    p.get = [field](const P &params) { return static_cast<double>(params.*field); };
    p.set = [field](P &params, double v) {
        if constexpr (std::is_same_v<T, bool>)
            params.*field = v != 0.0;
        else
            params.*field = static_cast<T>(v);
    };
    return p;
}

template <class P>
class ParamTable {
public:
    explicit ParamTable(std::string algorithm) : m_algorithm(std::move(algorithm)) {}

    // The name in messages and section titles: "remesh".
    const std::string &algorithm() const { return m_algorithm; }
    const std::vector<Param<P>> &params() const { return m_params; }

    // Appends an entry; its default is read from P{}.
    void add(Param<P> param)
    {
        const P defaults{};
        if (param.info.type != ParamType::IntList)
            param.info.defaultValue = param.get(defaults);
        else
            param.info.defaultList = param.getList(defaults);
        m_params.push_back(std::move(param));
    }

    const Param<P> *find(const std::string &key) const
    {
        for (const Param<P> &p : m_params)
            if (p.info.key == key)
                return &p;
        return nullptr;
    }
    // A key that is not in the table is a programming error.
    const Param<P> &at(const std::string &key) const
    {
        if (const Param<P> *p = find(key))
            return *p;
        throw std::logic_error(m_algorithm + ": no parameter '" + key + "'");
    }
    const ParamInfo &info(const std::string &key) const { return at(key).info; }

    std::vector<ParamInfo> infos() const
    {
        std::vector<ParamInfo> all;
        for (const Param<P> &p : m_params)
            all.push_back(p.info);
        return all;
    }

private:
    std::string m_algorithm;
    std::vector<Param<P>> m_params;
};

// A number as short as it reads back exactly: 0.4, 10000000, 1e+300.
std::string formatParamNumber(double value);
// "[4, 10000000] or 0", with the unit.
std::string paramRangeText(const ParamInfo &info);
// Empty when `value` is accepted; otherwise why not, with the range: "is 2, outside [4, ...]".
std::string paramValueError(const ParamInfo &info, double value);

// InputError "ALGORITHM: KEY is 2, outside [4, 10000000] or 0" for the first value out of its
// range (every element of a list).
void throwParamError(const std::string &algorithm, const ParamInfo &info, const std::string &why);
template <class P>
void checkParams(const ParamTable<P> &table, const P &params)
{
    for (const Param<P> &p : table.params()) {
        if (p.info.type == ParamType::IntList) {
            for (double v : p.getList(params))
                if (const std::string why = paramValueError(p.info, v); !why.empty())
                    throwParamError(table.algorithm(), p.info, why);
        } else if (const std::string why = paramValueError(p.info, p.get(params)); !why.empty()) {
            throwParamError(table.algorithm(), p.info, why);
        }
    }
}

} // namespace stratamesh
