#include "about_dialog.h"

#include "common/version.h"

#include <QCoreApplication>
#include <QMessageBox>

namespace stratamesh {

void showAboutDialog(QWidget *parent)
{
    const QString html =
        QStringLiteral("<h3>StrataMesh %1</h3><p>%2</p><p>%3</p><p>%4</p><p>%5</p>")
            .arg(QStringLiteral(STRATAMESH_VERSION),
                 QCoreApplication::translate("AboutDialog",
                                             "Remeshing and meshing of 3D structural models: "
                                             "conformal surface remeshing with "
                                             "restricted Voronoi diagrams, complexity measures and "
                                             "TetGen comparison meshes, after "
                                             "J. Pellerin's PhD thesis."),
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
    QMessageBox::about(parent, QCoreApplication::translate("AboutDialog", "About StrataMesh"),
                       html);
}

} // namespace stratamesh
