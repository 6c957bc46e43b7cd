// stratamesh-cli synthetic (layered|network|spheres|sample) [--faults N] [--dip D] [--horizons H]
//     [--throw T] [--edge-length L] [--thin-layer T] [--inner-radius 1] [--middle-radius 0]
//     [--outer-radius 2] -o OUT [--overwrite]
// Writes one of the models the tests are built on, so that a user or an acceptance run can try
// the same difficulties from the command line (fault networks: low-dip faults, throws below and
// above the remesh edge length, horizons cut into many pieces).
#include "cli_output.h"
#include "command_args.h"
#include "io/mesh_writer.h"
#include "io/output_plan.h"
#include "model/synthetic_models.h"
#include "model/topology.h"

#include <QFileInfo>

namespace stratamesh::cli {

int runSynthetic(CommandArgs &args)
{
    const int faults = args.intOption(QStringLiteral("--faults"), 3, 1, 10);
    const double dip = args.doubleOption(QStringLiteral("--dip"), 30.0, 1.0, 90.0);
    const int horizons = args.intOption(QStringLiteral("--horizons"), 3, 0, 50);
    const double throwUnit = args.doubleOption(QStringLiteral("--throw"), 20.0, 0.0, 1e4);
    const double edge = args.doubleOption(QStringLiteral("--edge-length"), 40.0, 1.0, 1e4);
    // layered: a layer this thick above the lowest horizon (0: none), where hybrid meshes get
    // their prisms (thesis §5.3.2).
    const double thin = args.doubleOption(QStringLiteral("--thin-layer"), 0.0, 0.0, 1e4);
    // spheres: radii of the inner, middle (0: none) and outer spheres.
    const double inner = args.doubleOption(QStringLiteral("--inner-radius"), 1.0, 1e-9, 1e9);
    const double middle = args.doubleOption(QStringLiteral("--middle-radius"), 0.0, 0.0, 1e9);
    const double outer = args.doubleOption(QStringLiteral("--outer-radius"), 2.0, 1e-9, 1e9);
    const bool overwrite = args.flag(QStringLiteral("--overwrite"));
    const std::optional<QString> output = args.option(QStringLiteral("-o"));
    const QString kind = args.positional(QStringLiteral("KIND"));
    args.finish();
    if (!output)
        throw UsageError(QStringLiteral("missing -o OUT"));
    OutputPlan plan({}, overwrite);
    plan.add(output->toStdString(), "model");
    Model model;
    if (kind == QLatin1String("network")) {
        model = faultNetworkBox(faults, dip, horizons, throwUnit, edge);
    } else if (kind == QLatin1String("layered")) {
        LayeredBoxParams p;
        p.horizons = horizons;
        p.edgeLength = edge;
        p.thinLayerThickness = thin;
        model = layeredBox(p);
    } else if (kind == QLatin1String("spheres")) {
        NestedSpheresParams p;
        p.innerRadius = inner;
        p.middleRadius = middle;
        p.outerRadius = outer;
        model = nestedSpheres(p);
    } else if (kind == QLatin1String("sample")) {
        model = sampleModel();
    } else {
        throw UsageError(
            QStringLiteral("unknown model '%1': layered, network, spheres or sample").arg(kind));
    }
    ExportReport report;
    plan.write(output->toStdString(), [&](const std::string &temporary) {
        report = exportModel(recoverTopology(model), temporary);
    });
    plan.commit();
    out() << "wrote " << *output << " (" << QString::fromStdString(report.format)
          << "): " << model.surfaces.size() << " surfaces, " << model.triangleCount()
          << " triangles, " << model.regions.size() << " regions\n";
    return 0;
}

} // namespace stratamesh::cli
