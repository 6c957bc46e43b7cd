#include "quality/model_comparison.h"

#include "common/error.h"

#include <cstdio>

namespace stratamesh {

namespace {

std::string fixed(double value, int decimals)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

} // namespace

ModelComparison compareModels(const Model &input, const Model &output,
                              const HausdorffParams &params, Progress &progress)
{
    return compareModels(input, output, hausdorffDistance(input, output, params, progress));
}

ModelComparison compareModels(const Model &input, const Model &output,
                              const HausdorffResult &measured)
{
    ModelComparison c;
    c.input.label = c.output.label = input.name;
    c.input.resolution = "Input";
    c.input.mesh = computeMeshStatistics(input);
    c.output.mesh = computeMeshStatistics(output);
    c.input.counts = countEntities(input).withoutBox;
    c.output.counts = countEntities(output).withoutBox;
    c.inputMinAngle = minAngleHistogram(input);
    c.outputMinAngle = minAngleHistogram(output);
    c.inputQuality = qualityHistogram(input);
    c.outputQuality = qualityHistogram(output);
    c.hausdorff = measured;
    c.output.hausdorffPctBbox = c.hausdorff.symmetricPctBbox;
    return c;
}

ModelComparison compareRuns(const ModelComparison &first, const ModelComparison &second)
{
    if (first.input.mesh.vertices != second.input.mesh.vertices
        || first.input.mesh.triangles != second.input.mesh.triangles
        || first.input.label != second.input.label)
        throw InputError("the two runs were not made from the same input model");
    ModelComparison c;
    c.input = first.output;
    c.output = second.output;
    c.hausdorff = second.hausdorff;
    c.inputMinAngle = first.outputMinAngle;
    c.outputMinAngle = second.outputMinAngle;
    c.inputQuality = first.outputQuality;
    c.outputQuality = second.outputQuality;
    return c;
}

std::string formatTable42(const std::vector<ComparisonRow> &rows)
{
    std::string out =
        "| Dataset | #Sites | #V | #T | #Surf. | #Lines | #Corners | Min angle | < 30° (%) | Avg Q "
        "| Area | Sampling (s) | Mesh (s) | Haus. (% bbox diag.) | Bbox diag. |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    char buffer[512];
    for (const ComparisonRow &r : rows) {
        const bool input = r.hausdorffPctBbox < 0.0;
        std::snprintf(buffer, sizeof buffer,
                      "| %s | %s | %zu | %zu | %d | %d | %d | %.2f | %.2f | %.3f | %.4g | %s | %s "
                      "| %s | %.6g |\n",
                      r.label.c_str(), r.resolution.c_str(), r.mesh.vertices, r.mesh.triangles,
                      r.counts.surfaces, r.counts.lines, r.counts.corners, r.mesh.minAngleDeg,
                      r.mesh.pctTrianglesAngleBelow30, r.mesh.meanQuality, r.mesh.area,
                      input ? "" : fixed(r.samplingSeconds, 2).c_str(),
                      input ? "" : fixed(r.meshSeconds, 2).c_str(),
                      input ? "" : fixed(r.hausdorffPctBbox, 3).c_str(), r.mesh.bboxDiagonal);
        out += buffer;
    }
    return out;
}

} // namespace stratamesh
