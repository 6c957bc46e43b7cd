// The layered box is one structured grid per fault block: indices (k, j, s) along (x, y, z).
// Every surface patch is a rectangle of a grid plane, and every point comes from point(), so two
// patches meeting along a contact produce bit-identical vertices there.
#include "model/synthetic_models.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace stratamesh {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Exact at both ends, so grid lines shared by two patches or blocks meet bit for bit.
double lerp(double a, double b, int k, int n)
{
    if (k == 0)
        return a;
    if (k == n)
        return b;
    return a + (b - a) * (static_cast<double>(k) / n);
}

int steps(double length, double h)
{
    return std::max(1, static_cast<int>(std::lround(length / h)));
}

struct Level {
    double c;
    bool flat; // z = c, else z = c + fold(y)
};

// A fault block lies between fault `index - 1` (or the box's west face) and fault `index` (or
// the east face).
struct Block {
    int index = 0;
    int nx = 1;
    std::vector<int> levels;   // level indices bounding its layers, bottom to top (incl. box)
    std::vector<int> features; // horizon feature number of each interior level (1-based)
    std::string suffix;        // appended to surface/region names
};

class LayeredBoxBuilder {
public:
    explicit LayeredBoxBuilder(const LayeredBoxParams &p) : m_p(p)
    {
        if (m_p.faultPositions.empty() && m_p.fault) {
            m_p.faultPositions = {m_p.faultPosition};
            m_p.faultThrows = {m_p.faultThrow};
        }
        m_p.fault = !m_p.faultPositions.empty();
        validate();
    }

    Model build()
    {
        setUpLevels();
        Model model;
        model.name = faultCount() > 1 ? "fault_network_box"
                     : m_p.fault      ? "layered_box_fault"
                                      : "layered_box";
        for (Block &b : m_blocks)
            addBlock(model, b);
        for (int f = 0; f < faultCount(); ++f)
            addFault(model, f);
        groupLayers(model);
        return model;
    }

private:
    void validate() const
    {
        const Vec3 &s = m_p.size;
        if (!(s.x() > 0 && s.y() > 0 && s.z() > 0) || !(m_p.edgeLength > 0))
            throw InputError("layered box: the size and the edge length must be positive");
        if (m_p.faultThrows.size() != m_p.faultPositions.size())
            throw InputError("layered box: give one throw per fault position");
        for (std::size_t f = 0; f < m_p.faultThrows.size(); ++f)
            if (!(m_p.faultThrows[f] >= 0)
                || (f > 0 && !(m_p.faultPositions[f] > m_p.faultPositions[f - 1])))
                throw InputError(
                    "layered box: throws must not be negative and fault positions must increase");
        if (m_p.horizons < 0 || !(m_p.foldAmplitude >= 0) || !(m_p.faultThrow >= 0)
            || !(m_p.thinLayerThickness >= 0))
            throw InputError(
                "layered box: horizons, fold amplitude, throw and thin layer must not be negative");
        if (room() <= 0)
            throw InputError(
                "layered box: the fold amplitude and the throw leave no room for the horizons");
        if (m_p.thinLayerThickness > 0
            && (m_p.horizons == 0 || m_p.thinLayerThickness >= room() / (m_p.horizons + 1)))
            throw InputError("layered box: the thin layer needs a horizon below it and must be "
                             "thinner than a layer");
        if (m_p.fault && !(m_p.faultDipDegrees > 0 && m_p.faultDipDegrees <= 90))
            throw InputError("layered box: the fault dip must be in (0, 90] degrees");
        for (int f = 0; f < faultCount(); ++f)
            if (!(faultX(f, 0.0) < s.x() && faultX(f, s.z()) > 0.0 && faultX(f, 0.0) > 0.0
                  && faultX(f, s.z()) < s.x()))
                throw InputError(
                    "layered box: the fault must cross the box through its top and bottom faces");
        if (!m_p.fault && m_p.faultThrow > 0)
            throw InputError("layered box: a throw needs a fault");
    }

    int faultCount() const { return static_cast<int>(m_p.faultPositions.size()); }
    // How far the horizons of fault block b are lowered: the throws of the faults west of it.
    double offset(int block) const
    {
        double o = 0.0;
        for (int f = 0; f < block; ++f)
            o += m_p.faultThrows[f];
        return o;
    }
    double room() const { return m_p.size.z() - m_p.foldAmplitude - offset(faultCount()); }
    double fold(double y) const { return m_p.foldAmplitude * std::sin(kPi * y / m_p.size.y()); }
    double levelZ(const Level &l, double y) const { return l.flat ? l.c : l.c + fold(y); }

    // The fault plane, dipping towards +x: x decreases upwards.
    double faultX(int f, double z) const
    {
        const double cot =
            m_p.faultDipDegrees == 90.0 ? 0.0 : 1.0 / std::tan(m_p.faultDipDegrees * kPi / 180.0);
        return m_p.faultPositions[f] * m_p.size.x() + (0.5 * m_p.size.z() - z) * cot;
    }
    double westX(const Block &b, double z) const
    {
        return b.index == 0 ? 0.0 : faultX(b.index - 1, z);
    }
    double eastX(const Block &b, double z) const
    {
        return b.index == faultCount() ? m_p.size.x() : faultX(b.index, z);
    }

    void setUpLevels()
    {
        const double h = m_p.edgeLength;
        const double throwZ = offset(faultCount());
        std::vector<double> horizons;
        for (int i = 0; i < m_p.horizons; ++i)
            horizons.push_back(throwZ + room() * (i + 1) / (m_p.horizons + 1));
        if (m_p.thinLayerThickness > 0)
            horizons.push_back(horizons.front() + m_p.thinLayerThickness);
        std::sort(horizons.begin(), horizons.end());

        // Levels: bottom, top and every horizon of every block, merged when exactly equal.
        std::map<double, int> curved;
        for (double c : horizons)
            for (int b = 0; b <= faultCount(); ++b)
                curved[c - offset(b)] = 0;
        m_levels.push_back({0.0, true});
        for (auto &[c, index] : curved) {
            index = static_cast<int>(m_levels.size());
            m_levels.push_back({c, false});
        }
        m_levels.push_back({m_p.size.z(), true});

        // Samples along z: each band between consecutive levels gets a fixed number of steps.
        m_levelSample.assign(m_levels.size(), 0);
        std::vector<int> bandSteps;
        const double meanFold = 2.0 / kPi * m_p.foldAmplitude;
        for (std::size_t q = 0; q + 1 < m_levels.size(); ++q) {
            const double lo = m_levels[q].c + (m_levels[q].flat ? 0.0 : meanFold);
            const double hi = m_levels[q + 1].c + (m_levels[q + 1].flat ? 0.0 : meanFold);
            bandSteps.push_back(steps(hi - lo, h));
            m_levelSample[q + 1] = m_levelSample[q] + bandSteps.back();
        }
        m_samples = m_levelSample.back();

        m_ny = steps(m_p.size.y(), h);
        m_y.resize(m_ny + 1);
        for (int j = 0; j <= m_ny; ++j)
            m_y[j] = lerp(0.0, m_p.size.y(), j, m_ny);
        m_z.assign(m_ny + 1, std::vector<double>(m_samples + 1));
        for (int j = 0; j <= m_ny; ++j)
            for (std::size_t q = 0; q + 1 < m_levels.size(); ++q) {
                const double lo = levelZ(m_levels[q], m_y[j]), hi = levelZ(m_levels[q + 1], m_y[j]);
                for (int t = 0; t <= bandSteps[q]; ++t)
                    m_z[j][m_levelSample[q] + t] = lerp(lo, hi, t, bandSteps[q]);
            }

        auto blockLevels = [&](double offset, Block &b) {
            b.levels.push_back(0);
            for (std::size_t i = 0; i < horizons.size(); ++i) {
                b.levels.push_back(curved.at(horizons[i] - offset));
                b.features.push_back(static_cast<int>(i) + 1);
            }
            b.levels.push_back(static_cast<int>(m_levels.size()) - 1);
        };
        const double mid = 0.5 * m_p.size.z();
        for (int i = 0; i <= faultCount(); ++i) {
            Block b;
            b.index = i;
            b.nx = steps(eastX(b, mid) - westX(b, mid), h);
            b.suffix = faultCount() == 0   ? ""
                       : faultCount() == 1 ? (i == 0 ? "_west" : "_east")
                                           : "_b" + std::to_string(i);
            blockLevels(offset(i), b);
            m_blocks.push_back(b);
        }
    }

    Vec3 point(const Block &b, int k, int j, int s) const
    {
        const double z = m_z[j][s];
        return {lerp(westX(b, z), eastX(b, z), k, b.nx), m_y[j], z};
    }

    // A surface from the grid rectangle [u0, u1] × [v0, v1]; normals along ∂p/∂u × ∂p/∂v.
    static int addPatch(Model &model, const std::string &name, const std::string &feature,
                        FeatureType type, const std::function<Vec3(int, int)> &at, int u0, int u1,
                        int v0, int v1)
    {
        Surface s;
        s.name = name;
        s.featureName = feature;
        s.sourceObject = feature;
        s.type = type;
        const int nu = u1 - u0 + 1;
        for (int v = v0; v <= v1; ++v)
            for (int u = u0; u <= u1; ++u)
                s.vertices.push_back(at(u, v));
        auto id = [&](int u, int v) { return (v - v0) * nu + (u - u0); };
        for (int v = v0; v < v1; ++v)
            for (int u = u0; u < u1; ++u) {
                s.triangles.push_back({id(u, v), id(u + 1, v), id(u + 1, v + 1)});
                s.triangles.push_back({id(u, v), id(u + 1, v + 1), id(u, v + 1)});
            }
        model.surfaces.push_back(std::move(s));
        return static_cast<int>(model.surfaces.size()) - 1;
    }

    void addBlock(Model &model, Block &b)
    {
        const int nx = b.nx, ny = m_ny, top = m_samples;
        const FeatureType box = FeatureType::Boundary;
        const std::size_t layers = b.levels.size() - 1;
        const std::size_t firstRegion = model.regions.size();
        for (std::size_t l = 0; l < layers; ++l) {
            Region r;
            r.name = "layer" + std::to_string(l + 1) + b.suffix;
            model.regions.push_back(r);
        }
        auto side = [&](std::size_t layer, int surface, bool positive) {
            model.regions[firstRegion + layer].boundaries.push_back({surface, positive});
        };
        auto boxSide = [&](std::size_t layer, int surface) {
            side(layer, surface, false); // box normals point out of the box
            model.universe.push_back({surface, true});
        };

        boxSide(0, addPatch(
                       model, "box_bottom" + b.suffix, "box", box,
                       [&](int u, int v) { return point(b, v, u, 0); }, 0, ny, 0, nx));
        boxSide(layers - 1, addPatch(
                                model, "box_top" + b.suffix, "box", box,
                                [&](int u, int v) { return point(b, u, v, top); }, 0, nx, 0, ny));
        for (std::size_t i = 0; i < b.features.size(); ++i) {
            const int s = m_levelSample[b.levels[i + 1]];
            const std::string feature = "H" + std::to_string(b.features[i]);
            const int surface = addPatch(
                model, feature + b.suffix, feature, FeatureType::Horizon,
                [&](int u, int v) { return point(b, u, v, s); }, 0, nx, 0, ny);
            side(i, surface, false); // normal up: the layer below is on its negative side
            side(i + 1, surface, true);
        }
        for (std::size_t l = 0; l < layers; ++l) {
            const int s0 = m_levelSample[b.levels[l]], s1 = m_levelSample[b.levels[l + 1]];
            const std::string n = std::to_string(l + 1) + b.suffix;
            if (b.index == 0)
                boxSide(l, addPatch(
                               model, "box_west_" + n, "box", box,
                               [&](int u, int v) { return point(b, 0, v, u); }, s0, s1, 0, ny));
            if (b.index == faultCount())
                boxSide(l, addPatch(
                               model, "box_east_" + n, "box", box,
                               [&](int u, int v) { return point(b, nx, u, v); }, 0, ny, s0, s1));
            boxSide(l, addPatch(
                           model, "box_south_" + n, "box", box,
                           [&](int u, int v) { return point(b, u, 0, v); }, 0, nx, s0, s1));
            boxSide(l, addPatch(
                           model, "box_north_" + n, "box", box,
                           [&](int u, int v) { return point(b, v, ny, u); }, s0, s1, 0, nx));
        }
    }

    // Fault patches between every level met by a horizon of either block; normal towards +x.
    void addFault(Model &model, int f)
    {
        const Block &west = m_blocks[f];
        const Block &east = m_blocks[f + 1];
        const std::size_t layers = west.levels.size() - 1;
        const std::string feature = "F" + std::to_string(f + 1);
        std::vector<int> cuts(west.levels);
        cuts.insert(cuts.end(), east.levels.begin(), east.levels.end());
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        auto layerOf = [](const Block &b, int level) {
            return static_cast<std::size_t>(
                       std::upper_bound(b.levels.begin(), b.levels.end(), level) - b.levels.begin())
                   - 1;
        };
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            const int s0 = m_levelSample[cuts[i]], s1 = m_levelSample[cuts[i + 1]];
            const int surface = addPatch(
                model, feature + "_" + std::to_string(i + 1), feature, FeatureType::Fault,
                [&](int u, int v) { return point(west, west.nx, u, v); }, 0, m_ny, s0, s1);
            const std::size_t wl = layerOf(west, cuts[i]), el = layerOf(east, cuts[i]);
            model.regions[f * layers + wl].boundaries.push_back({surface, false});
            model.regions[(f + 1) * layers + el].boundaries.push_back({surface, true});
        }
    }

    void groupLayers(Model &model) const
    {
        const std::size_t layers = m_blocks[0].levels.size() - 1;
        for (std::size_t l = 0; l < layers; ++l) {
            Layer layer;
            layer.name = "layer" + std::to_string(l + 1);
            for (std::size_t b = 0; b < m_blocks.size(); ++b)
                layer.regions.push_back(static_cast<int>(b * layers + l));
            model.layers.push_back(layer);
        }
    }

    LayeredBoxParams m_p;
    std::vector<Level> m_levels;
    std::vector<int> m_levelSample;
    int m_samples = 0;
    int m_ny = 1;
    std::vector<double> m_y;
    std::vector<std::vector<double>> m_z; // [j][s]
    std::vector<Block> m_blocks;
};

} // namespace

Model layeredBox(const LayeredBoxParams &params)
{
    return LayeredBoxBuilder(params).build();
}

Model faultNetworkBox(int faults, double dipDegrees, int horizons, double throwUnit,
                      double edgeLength)
{
    if (faults < 1 || faults > 10)
        throw InputError("fault network box: between 1 and 10 faults");
    LayeredBoxParams p;
    const double cot = 1.0 / std::tan(dipDegrees * kPi / 180.0);
    p.size = {(faults + 1) * (400.0 * cot + 4.0 * throwUnit + 2.0 * edgeLength), 1500.0, 400.0};
    p.horizons = horizons;
    p.foldAmplitude = 40.0;
    p.faultDipDegrees = dipDegrees;
    p.edgeLength = edgeLength;
    const double throws[] = {0.3, 1.5, 0.6, 2.5};
    for (int f = 0; f < faults; ++f) {
        p.faultPositions.push_back((f + 1.0) / (faults + 1.0));
        p.faultThrows.push_back(throws[f % 4] * throwUnit);
    }
    Model m = layeredBox(p);
    m.name = "fault_network_" + std::to_string(faults);
    return m;
}

Model sampleModel()
{
    LayeredBoxParams p;
    p.size = {1600.0, 930.0, 500.0};
    p.horizons = 3;
    p.foldAmplitude = 90.0;
    p.fault = true;
    p.faultDipDegrees = 60.0;
    p.faultPosition = 0.55;
    p.faultThrow = 50.0;
    p.edgeLength = 70.0;
    Model m = layeredBox(p);
    m.name = "sample";
    return m;
}

} // namespace stratamesh
