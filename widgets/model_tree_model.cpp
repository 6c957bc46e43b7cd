#include "model_tree_model.h"

#include "complexity/element_sizes.h"

#include <QApplication>
#include <QLocale>
#include <QPalette>

#include <map>

namespace stratamesh {

namespace {

QString typeWord(FeatureType type)
{
    switch (type) {
    case FeatureType::Horizon:
        return ModelTreeModel::tr("horizon");
    case FeatureType::Fault:
        return ModelTreeModel::tr("fault");
    case FeatureType::Unconformity:
        return ModelTreeModel::tr("unconformity");
    case FeatureType::Boundary:
        return ModelTreeModel::tr("box");
    case FeatureType::Unknown:
        break;
    }
    return ModelTreeModel::tr("other");
}

// Regions list their sides' surfaces for the highlight, but carry no check box: a surface is
// shared by two regions, so hiding a region is not hiding its surfaces.
bool checkable(ModelTreeModel::Kind kind, bool hasSurfaces)
{
    return hasSurfaces
           && (kind == ModelTreeModel::Kind::Surface || kind == ModelTreeModel::Kind::Group);
}

QString number(double value)
{
    return QLocale().toString(value, 'g', 6);
}

} // namespace

ModelTreeModel::ModelTreeModel(QObject *parent) : QAbstractItemModel(parent)
{
    m_nodes.emplace_back();
}

ModelTreeModel::~ModelTreeModel() = default;

void ModelTreeModel::setModel(std::shared_ptr<const Model> model)
{
    beginResetModel();
    m_model = std::move(model);
    build();
    endResetModel();
}

int ModelTreeModel::addNode(int parent, Node node)
{
    const int id = int(m_nodes.size());
    node.parent = parent;
    node.row = int(m_nodes[std::size_t(parent)].children.size());
    m_nodes[std::size_t(parent)].children.push_back(id);
    m_nodes.push_back(std::move(node));
    return id;
}

void ModelTreeModel::build()
{
    m_nodes.assign(1, Node{});
    m_surfaceNode.clear();
    m_lineNode.clear();
    m_cornerNode.clear();
    m_regionNode.clear();
    m_visible.clear();
    if (!m_model)
        return;
    const Model &model = *m_model;
    m_visible.assign(model.surfaces.size(), true);
    m_surfaceNode.assign(model.surfaces.size(), -1);
    const auto group = [](Group g) {
        Node n;
        n.group = g;
        return n;
    };
    const auto entityNode = [](Kind kind, int entity, const std::string &name) {
        Node n;
        n.kind = kind;
        n.entity = entity;
        n.name = QString::fromStdString(name);
        return n;
    };

    const int regions = addNode(0, group(Group::Regions));
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
        Node n = entityNode(Kind::Region, int(r), model.regions[r].name);
        for (const RegionSide &side : model.regions[r].boundaries)
            if (side.surface >= 0 && std::size_t(side.surface) < model.surfaces.size())
                n.surfaces.push_back(side.surface);
        m_regionNode.push_back(addNode(regions, std::move(n)));
    }

    // Types in the legend's order; features in order of first appearance. A feature made of one
    // surface is listed without a level of its own.
    const int surfaces = addNode(0, group(Group::Surfaces));
    const std::pair<FeatureType, Group> types[] = {
        {FeatureType::Horizon, Group::Horizons},
        {FeatureType::Unconformity, Group::Unconformities},
        {FeatureType::Fault, Group::Faults},
        {FeatureType::Unknown, Group::Other},
        {FeatureType::Boundary, Group::Box}};
    for (const auto &[type, groupKind] : types) {
        std::vector<std::string> features;
        std::map<std::string, std::vector<int>> members;
        for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
            const Surface &surface = model.surfaces[s];
            if (surface.type != type)
                continue;
            auto &list = members[surface.featureName];
            if (list.empty())
                features.push_back(surface.featureName);
            list.push_back(int(s));
        }
        if (features.empty())
            continue;
        const int typeNode = addNode(surfaces, group(groupKind));
        for (const std::string &feature : features) {
            const std::vector<int> &list = members[feature];
            int parent = typeNode;
            if (list.size() > 1) {
                Node f = group(Group::Feature);
                f.name = QString::fromStdString(feature);
                parent = addNode(typeNode, std::move(f));
            }
            for (int s : list) {
                Node n = entityNode(Kind::Surface, s, model.surfaces[std::size_t(s)].name);
                n.surfaces = {s};
                m_surfaceNode[std::size_t(s)] = addNode(parent, std::move(n));
                // Every group above lists the surface for its check state.
                for (int p = parent; p > 0; p = m_nodes[std::size_t(p)].parent)
                    m_nodes[std::size_t(p)].surfaces.push_back(s);
            }
        }
    }

    const int lines = addNode(0, group(Group::Lines));
    for (std::size_t l = 0; l < model.lines.size(); ++l)
        m_lineNode.push_back(addNode(lines, entityNode(Kind::Line, int(l), model.lines[l].name)));
    const int corners = addNode(0, group(Group::Corners));
    for (std::size_t c = 0; c < model.corners.size(); ++c)
        m_cornerNode.push_back(
            addNode(corners, entityNode(Kind::Corner, int(c), "corner_" + std::to_string(c))));
}

void ModelTreeModel::setSurfacesVisible(const QList<int> &surfaces, bool visible)
{
    for (int s : surfaces) {
        if (s < 0 || std::size_t(s) >= m_visible.size() || m_visible[std::size_t(s)] == visible)
            continue;
        m_visible[std::size_t(s)] = visible;
        emitChanged(m_surfaceNode[std::size_t(s)]);
    }
}

bool ModelTreeModel::surfaceVisible(int surface) const
{
    return surface >= 0 && std::size_t(surface) < m_visible.size()
           && m_visible[std::size_t(surface)];
}

void ModelTreeModel::setBoxShown(bool shown)
{
    if (m_boxShown == shown)
        return;
    m_boxShown = shown;
    for (std::size_t i = 1; i < m_nodes.size(); ++i)
        if (m_nodes[i].group == Group::Box) {
            const QModelIndex box = createIndex(m_nodes[i].row, 0, quintptr(i));
            emit dataChanged(box, box, {Qt::ForegroundRole});
            const int rows = rowCount(box);
            if (rows > 0)
                emit dataChanged(index(0, 0, box), index(rows - 1, 0, box), {Qt::ForegroundRole});
        }
}

void ModelTreeModel::emitChanged(int id)
{
    for (int n = id; n > 0; n = m_nodes[std::size_t(n)].parent) {
        const QModelIndex i = createIndex(m_nodes[std::size_t(n)].row, 0, quintptr(n));
        emit dataChanged(i, i, {Qt::CheckStateRole});
    }
}

int ModelTreeModel::entityCount(Kind kind) const
{
    switch (kind) {
    case Kind::Region:
        return int(m_regionNode.size());
    case Kind::Surface:
        return int(m_surfaceNode.size());
    case Kind::Line:
        return int(m_lineNode.size());
    case Kind::Corner:
        return int(m_cornerNode.size());
    case Kind::Group:
        break;
    }
    int groups = 0;
    for (const Node &n : m_nodes)
        groups += n.kind == Kind::Group ? 1 : 0;
    return groups - 1; // not the root
}

QModelIndex ModelTreeModel::indexOf(Kind kind, int entity) const
{
    const std::vector<int> *nodes = nullptr;
    switch (kind) {
    case Kind::Region:
        nodes = &m_regionNode;
        break;
    case Kind::Surface:
        nodes = &m_surfaceNode;
        break;
    case Kind::Line:
        nodes = &m_lineNode;
        break;
    case Kind::Corner:
        nodes = &m_cornerNode;
        break;
    case Kind::Group:
        return {};
    }
    if (entity < 0 || std::size_t(entity) >= nodes->size())
        return {};
    const int id = (*nodes)[std::size_t(entity)];
    return createIndex(m_nodes[std::size_t(id)].row, 0, quintptr(id));
}

const ModelTreeModel::Node &ModelTreeModel::node(const QModelIndex &index) const
{
    const quintptr id = index.isValid() ? index.internalId() : 0;
    return m_nodes[id < m_nodes.size() ? id : 0];
}

ModelTreeModel::Kind ModelTreeModel::kind(const QModelIndex &index) const
{
    return node(index).kind;
}

int ModelTreeModel::entity(const QModelIndex &index) const
{
    return node(index).entity;
}

QList<int> ModelTreeModel::surfacesOf(const QModelIndex &index) const
{
    const Node &n = node(index);
    return QList<int>(n.surfaces.begin(), n.surfaces.end());
}

QString ModelTreeModel::title(const Node &n) const
{
    const auto counted = [&](const QString &what) {
        return QStringLiteral("%1 (%2)").arg(what).arg(n.children.size());
    };
    switch (n.group) {
    case Group::None:
        return n.name;
    case Group::Regions:
        return counted(tr("Regions"));
    case Group::Surfaces:
        return tr("Surfaces (%1)").arg(n.surfaces.size());
    case Group::Horizons:
        return tr("Horizons (%1)").arg(n.surfaces.size());
    case Group::Faults:
        return tr("Faults (%1)").arg(n.surfaces.size());
    case Group::Unconformities:
        return tr("Unconformities (%1)").arg(n.surfaces.size());
    case Group::Other:
        return tr("Other Surfaces (%1)").arg(n.surfaces.size());
    case Group::Box:
        return tr("Box (%1)").arg(n.surfaces.size());
    case Group::Feature:
        return counted(n.name);
    case Group::Lines:
        return counted(tr("Lines"));
    case Group::Corners:
        return counted(tr("Corners"));
    }
    return n.name;
}

Qt::CheckState ModelTreeModel::checkState(const Node &n) const
{
    int shown = 0;
    for (int s : n.surfaces)
        shown += m_visible[std::size_t(s)] ? 1 : 0;
    if (shown == 0)
        return Qt::Unchecked;
    return shown == int(n.surfaces.size()) ? Qt::Checked : Qt::PartiallyChecked;
}

bool ModelTreeModel::isBoxRow(const Node &n) const
{
    if (n.group == Group::Box)
        return true;
    if (n.kind == Kind::Surface)
        return m_model->surfaces[std::size_t(n.entity)].type == FeatureType::Boundary;
    return n.group == Group::Feature && n.parent > 0
           && m_nodes[std::size_t(n.parent)].group == Group::Box;
}

QVariant ModelTreeModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid())
        return {};
    const Node &n = node(index);
    switch (role) {
    case Qt::DisplayRole:
        return title(n);
    case NameRole:
        return n.kind == Kind::Group && n.group != Group::Feature ? QString() : n.name;
    case KindRole:
        return int(n.kind);
    case EntityRole:
        return n.entity;
    case Qt::ToolTipRole:
        return describe(index);
    case Qt::CheckStateRole:
        if (checkable(n.kind, !n.surfaces.empty()))
            return checkState(n);
        return {};
    case Qt::ForegroundRole:
        if (!m_boxShown && isBoxRow(n))
            return QApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    default:
        return {};
    }
}

bool ModelTreeModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const Node &n = node(index);
    if (role != Qt::CheckStateRole || !checkable(n.kind, !n.surfaces.empty()))
        return false;
    const bool visible = value.toInt() != Qt::Unchecked;
    QList<int> changed;
    for (int s : n.surfaces)
        if (m_visible[std::size_t(s)] != visible)
            changed.append(s);
    if (!changed.isEmpty())
        emit visibilityRequested(changed, visible);
    return true;
}

Qt::ItemFlags ModelTreeModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    const Node &n = node(index);
    if (checkable(n.kind, !n.surfaces.empty()))
        f |= Qt::ItemIsUserCheckable;
    return f;
}

QModelIndex ModelTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (column != 0 || row < 0)
        return {};
    const Node &p = node(parent);
    if (std::size_t(row) >= p.children.size())
        return {};
    return createIndex(row, 0, quintptr(p.children[std::size_t(row)]));
}

QModelIndex ModelTreeModel::parent(const QModelIndex &child) const
{
    if (!child.isValid())
        return {};
    const int p = node(child).parent;
    if (p <= 0)
        return {};
    return createIndex(m_nodes[std::size_t(p)].row, 0, quintptr(p));
}

int ModelTreeModel::rowCount(const QModelIndex &parent) const
{
    if (parent.column() > 0)
        return 0;
    return int(node(parent).children.size());
}

int ModelTreeModel::columnCount(const QModelIndex &) const
{
    return 1;
}

QString ModelTreeModel::describe(const QModelIndex &index) const
{
    if (!m_model || !index.isValid())
        return {};
    const Model &model = *m_model;
    const Node &n = node(index);
    switch (n.kind) {
    case Kind::Surface: {
        const Surface &s = model.surfaces[std::size_t(n.entity)];
        return tr("Surface %1 — %2 %3, %n triangle(s)", nullptr, int(s.triangles.size()))
            .arg(n.name, typeWord(s.type), QString::fromStdString(s.featureName));
    }
    case Kind::Line: {
        const Line &l = model.lines[std::size_t(n.entity)];
        return tr("Line %1 — length %2, %n surface(s)", nullptr, int(l.surfaces.size()))
            .arg(n.name, number(lineLength(model, l)));
    }
    case Kind::Corner: {
        const Corner &c = model.corners[std::size_t(n.entity)];
        Vec3 p = Vec3::Zero();
        if (c.vertex >= 0 && std::size_t(c.vertex) < model.vertices.size())
            p = model.vertices[std::size_t(c.vertex)];
        return tr("Corner %1 at (%2, %3, %4) — %n line(s)", nullptr, int(c.lines.size()))
            .arg(n.name, number(p.x()), number(p.y()), number(p.z()));
    }
    case Kind::Region:
        return tr("Region %1 — %n boundary surface(s)", nullptr, int(n.surfaces.size()))
            .arg(n.name);
    case Kind::Group:
        break;
    }
    return title(n);
}

void ModelTreeModel::retranslate()
{
    emit layoutAboutToBeChanged();
    emit layoutChanged();
}

} // namespace stratamesh
