#include "param_form.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

#include <algorithm>
#include <climits>
#include <cmath>

namespace stratamesh {

namespace {

QString translated(const std::string &text)
{
    return text.empty() ? QString()
                        : QCoreApplication::translate(kParamTranslationContext, text.c_str());
}

// Decimals enough for lengths of 1/100 000 of the model's size (d_resolution is small), and
// for volumes of a millionth of its box.
int decimalsFor(const ParamInfo &info, double diagonal)
{
    if (info.decimals >= 0)
        return info.decimals;
    if (info.scale == ParamScale::Length)
        return diagonal > 0.0 ? std::clamp(int(std::ceil(5.0 - std::log10(diagonal))), 0, 8) : 3;
    if (info.scale == ParamScale::Volume)
        return std::clamp(int(std::ceil(6.0 - std::log10(diagonal * diagonal * diagonal))), 0, 8);
    return 3;
}

QString suffixFor(const ParamInfo &info)
{
    if (info.unit.empty())
        return {};
    const QString unit = translated(info.unit);
    return info.unit == "°" ? unit : QLatin1Char(' ') + unit;
}

} // namespace

QString paramLabel(const ParamInfo &info)
{
    return translated(info.label);
}

QString paramToolTip(const ParamInfo &info)
{
    QString tip = translated(info.help);
    if (!info.thesis.empty())
        tip += QLatin1Char(' ')
               + QCoreApplication::translate("stratamesh::ParamForm", "(thesis %1)")
                     .arg(QString::fromStdString(info.thesis));
    return tip;
}

QWidget *createParamField(const ParamInfo &info, double diagonal, QWidget *parent)
{
    const double scale = diagonal > 0.0 ? diagonal : 1.0;
    QWidget *field = nullptr;
    if (info.type == ParamType::Flag) {
        field = new QCheckBox(paramLabel(info), parent);
    } else if (info.type == ParamType::Real) {
        auto *box = new QDoubleSpinBox(parent);
        box->setDecimals(decimalsFor(info, scale));
        // A spin box as wide as 1e300 would fill the screen: lengths and volumes stop at the
        // model's size, the others at 1e15.
        double top = std::min(info.maximum, 1e15);
        if (info.scale == ParamScale::Length)
            top = std::min(top, scale);
        else if (info.scale == ParamScale::Volume)
            top = std::min(top, scale * scale * scale);
        box->setRange(info.minimum, top);
        if (info.decimals == 2)
            box->setSingleStep(0.05);
        else if (info.decimals == 3 && info.maximum > 1.0 && info.minimum < 1.0)
            box->setSingleStep(0.1);
        box->setSuffix(suffixFor(info));
        // At its minimum (0, or −1 for an automatic value that 0 cannot stand for) the box
        // names what the value means.
        if (info.minimum <= 0.0 && !info.offText.empty())
            box->setSpecialValueText(translated(info.offText));
        field = box;
    } else {
        auto *box = new QSpinBox(parent);
        box->setRange(int(std::max(info.minimum, double(INT_MIN))),
                      int(std::min(info.maximum, double(INT_MAX))));
        box->setGroupSeparatorShown(info.maximum >= 100000 && info.type != ParamType::Seed);
        box->setSuffix(suffixFor(info));
        if (info.minimum == 0.0 && !info.offText.empty())
            box->setSpecialValueText(translated(info.offText));
        field = box;
    }
    field->setObjectName(QString::fromStdString(info.key));
    field->setToolTip(paramToolTip(info));
    return field;
}

void setParamFieldValue(QWidget *field, double value)
{
    if (auto *check = qobject_cast<QCheckBox *>(field))
        check->setChecked(value != 0.0);
    else if (auto *real = qobject_cast<QDoubleSpinBox *>(field))
        real->setValue(value);
    else if (auto *whole = qobject_cast<QSpinBox *>(field))
        whole->setValue(int(std::clamp(value, double(INT_MIN), double(INT_MAX))));
}

double paramFieldValue(const QWidget *field)
{
    if (const auto *check = qobject_cast<const QCheckBox *>(field))
        return check->isChecked() ? 1.0 : 0.0;
    if (const auto *real = qobject_cast<const QDoubleSpinBox *>(field))
        return real->value();
    if (const auto *whole = qobject_cast<const QSpinBox *>(field))
        return whole->value();
    return 0.0;
}

void addParamRow(QFormLayout *form, const ParamInfo &info, QWidget *field)
{
    if (info.type == ParamType::Flag)
        form->addRow(field);
    else
        form->addRow(paramLabel(info), field);
}

} // namespace stratamesh
