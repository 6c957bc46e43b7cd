// Form fields made from a parameter table (core/params): one spin box or check box per entry,
// named after its key, with the entry's range, unit, translated label and tooltip (help and
// thesis reference). The dialogs lay them out; the values go to and from the params struct.
#pragma once

#include "params/param_table.h"

#include <QString>

#include <string>
#include <utility>
#include <vector>

class QFormLayout;
class QWidget;

namespace stratamesh {

// A QSpinBox (Int, Seed, the first number of an IntList), QDoubleSpinBox (Real) or QCheckBox
// (Flag). `diagonal`, the model's bounding-box diagonal, bounds and sets the decimals of
// lengths (ParamScale::Length) and volumes (ParamScale::Volume).
QWidget *createParamField(const ParamInfo &info, double diagonal, QWidget *parent);
void setParamFieldValue(QWidget *field, double value);
double paramFieldValue(const QWidget *field);
QString paramLabel(const ParamInfo &info);
QString paramToolTip(const ParamInfo &info);
// A label and its field, or a check box alone.
void addParamRow(QFormLayout *form, const ParamInfo &info, QWidget *field);

// The fields of a whole table, in its order.
template <class P>
class ParamFields {
public:
    ParamFields(const ParamTable<P> &table, double diagonal, QWidget *parent) : m_table(table)
    {
        for (const Param<P> &p : m_table.params())
            m_fields.push_back(createParamField(p.info, diagonal, parent));
        write(P{});
    }

    const ParamTable<P> &table() const { return m_table; }
    // nullptr when the table has no such key.
    QWidget *field(const std::string &key) const
    {
        for (std::size_t i = 0; i < m_fields.size(); ++i)
            if (m_table.params()[i].info.key == key)
                return m_fields[i];
        return nullptr;
    }

    // One row per field but those in `skip`: a label and its field, or a check box alone.
    void addRows(QFormLayout *form, const std::vector<std::string> &skip = {}) const
    {
        for (std::size_t i = 0; i < m_fields.size(); ++i) {
            const ParamInfo &info = m_table.params()[i].info;
            if (!contains(skip, info.key))
                addParamRow(form, info, m_fields[i]);
        }
    }

    void write(const P &params, const std::vector<std::string> &skip = {}) const
    {
        for (std::size_t i = 0; i < m_fields.size(); ++i) {
            const Param<P> &p = m_table.params()[i];
            if (contains(skip, p.info.key))
                continue;
            if (p.info.type == ParamType::IntList) {
                const std::vector<double> list = p.getList(params);
                if (!list.empty())
                    setParamFieldValue(m_fields[i], list.front());
            } else {
                setParamFieldValue(m_fields[i], p.get(params));
            }
        }
    }

    void read(P &params) const
    {
        for (std::size_t i = 0; i < m_fields.size(); ++i) {
            const Param<P> &p = m_table.params()[i];
            if (p.info.type == ParamType::IntList)
                p.setList(params, {paramFieldValue(m_fields[i])});
            else
                p.set(params, paramFieldValue(m_fields[i]));
        }
    }

private:
    static bool contains(const std::vector<std::string> &keys, const std::string &key)
    {
        for (const std::string &k : keys)
            if (k == key)
                return true;
        return false;
    }

    ParamTable<P> m_table;
    std::vector<QWidget *> m_fields;
};

} // namespace stratamesh
