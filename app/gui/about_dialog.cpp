#include "about_dialog.h"

#include "common/version.h"

#include <QCoreApplication>
#include <QMessageBox>

namespace stratamesh {

QString aboutText(const QStringList &offered)
{
    QString items;
    for (QString text : offered) {
        text.remove(QLatin1Char('&'));
        if (text.endsWith(QChar(0x2026)))
            text.chop(1);
        items += QStringLiteral("<li>%1</li>").arg(text.toHtmlEscaped());
    }
    return QStringLiteral("<h3>StrataMesh %1</h3><p>%2</p><ul>%3</ul><p>%4</p><p>%5</p><p>%6</p>")
        .arg(QStringLiteral(STRATAMESH_VERSION),
             QCoreApplication::translate(
                 "AboutDialog",
                 "Conformal remeshing and analysis of 3D structural models, after J. Pellerin's "
                 "PhD thesis. The menus offer:"),
             items,
             QCoreApplication::translate(
                 "AboutDialog",
                 "StrataMesh is free software: you can redistribute it and/or modify it under "
                 "the "
                 "terms of the GNU Affero General Public License, version 3 or (at your "
                 "option) any "
                 "later version (AGPL-3.0-or-later). It comes with no warranty."),
             QCoreApplication::translate(
                 "AboutDialog", "Tetrahedral comparison meshes are made by TetGen 1.5 (Hang "
                                "Si, WIAS Berlin), used "
                                "under the AGPL-3.0; TetGen runs in a separate process."),
             QCoreApplication::translate(
                 "AboutDialog",
                 "Built with Qt, VTK, CGAL, Eigen, OpenMesh, oneTBB, nanoflann and LBFGSpp."));
}

void showAboutDialog(QWidget *parent, const QStringList &offered)
{
    QMessageBox::about(parent, QCoreApplication::translate("AboutDialog", "About StrataMesh"),
                       aboutText(offered));
}

} // namespace stratamesh
