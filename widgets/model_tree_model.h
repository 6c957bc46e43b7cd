// The entities of a B-Rep model as a tree for the Model dock: Regions; Surfaces grouped by type
// (Horizons, Faults, Unconformities, Other, Box) and then by geological feature; Lines; Corners.
// Lines and corners are the ones the core's topology recovery found: nothing is computed here.
// Surfaces and their groups carry a visibility check box (tri-state for a group); a click on one
// only asks for the change (visibilityRequested), so that the caller can make it undoable and
// apply it with setSurfacesVisible().
#pragma once

#include "model/model.h"

#include <QAbstractItemModel>
#include <QList>

#include <memory>
#include <vector>

namespace stratamesh {

class ModelTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum class Kind { Group, Region, Surface, Line, Corner };
    enum Role {
        KindRole = Qt::UserRole + 1, // int(Kind)
        EntityRole,                  // index in the Model's vector, -1 for a group
        NameRole                     // what the search filters on: the entity's own name
    };

    explicit ModelTreeModel(QObject *parent = nullptr);
    ~ModelTreeModel() override;

    // Rebuilds the tree (nullptr empties it); every surface starts visible.
    void setModel(std::shared_ptr<const Model> model);
    const std::shared_ptr<const Model> &model() const { return m_model; }

    void setSurfacesVisible(const QList<int> &surfaces, bool visible);
    bool surfaceVisible(int surface) const;
    // While the box is hidden its rows are drawn greyed.
    void setBoxShown(bool shown);

    // Entities of one kind listed in the tree.
    int entityCount(Kind kind) const;
    QModelIndex indexOf(Kind kind, int entity) const;
    Kind kind(const QModelIndex &index) const;
    int entity(const QModelIndex &index) const;
    // The surfaces a row stands for: itself, a group's or a region's boundary surfaces.
    QList<int> surfacesOf(const QModelIndex &index) const;
    // One line for the status bar: what the row is, its type and size.
    QString describe(const QModelIndex &index) const;
    // Group titles are translated when shown: the language changed.
    void retranslate();

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;

signals:
    // The user checked or unchecked these surfaces (one surface or a group's).
    void visibilityRequested(const QList<int> &surfaces, bool visible);

private:
    enum class Group {
        None,
        Regions,
        Surfaces,
        Horizons,
        Faults,
        Unconformities,
        Other,
        Box,
        Feature,
        Lines,
        Corners
    };
    struct Node {
        Kind kind = Kind::Group;
        Group group = Group::None;
        int entity = -1;
        int parent = -1; // node index; -1 for the root
        int row = 0;
        QString name; // feature name for a feature group, entity name otherwise
        std::vector<int> children;
        std::vector<int> surfaces; // surfaces below (for check states)
    };

    int addNode(int parent, Node node);
    void build();
    const Node &node(const QModelIndex &index) const;
    QString title(const Node &node) const;
    Qt::CheckState checkState(const Node &node) const;
    bool isBoxRow(const Node &node) const;
    void emitChanged(int node);

    std::shared_ptr<const Model> m_model;
    std::vector<Node> m_nodes; // m_nodes[0] is the invisible root
    std::vector<bool> m_visible;
    std::vector<int> m_surfaceNode, m_lineNode, m_cornerNode, m_regionNode;
    bool m_boxShown = false;
};

} // namespace stratamesh
