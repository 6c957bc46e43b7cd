// The record of every change the remesher makes to a model (thesis §4.4.2–4.4.5, §4.6.1: "a
// quality check of the disappearing and appearing elements is necessary"). A geologist reviews
// these records one by one; each names what it touched, where, and how big the change was.
#pragma once

#include "common/message_text.h"
#include "model/model.h"

#include <string>
#include <vector>

namespace stratamesh {

enum class LedgerKind {
    CornerMerge,       // corners of one cell joined by a line merged (Alg 4.2 step 2, Fig 4.6b)
    MultiPointMerge,   // a cell component with > 2 points merged (Alg 4.2 step 3, Fig 4.6a)
    CloseFeatureMerge, // points of parts closer than d_resolution merged (Alg 4.2 step 4, Fig 4.7)
    DegenerateContactTriangle, // needle or cap along a contact removed (Alg 4.4, Fig 4.9)
    DegenerateBorderTriangle,  // degenerate triangle on a free border removed (Fig 4.8b)
    Valence3Removed,           // valence-3 interior vertex removed (Fig 4.8a)
    SurfaceLost,
    LineLost,
    CornerLost,
    SurfaceCreated,
    LineCreated,
    CornerCreated,
    IntersectionUnresolved, // intersecting output triangles left after repair (§4.4.5)
    // Surface parts: SurfaceLost/SurfaceCreated count whole surfaces (so that input − lost +
    // created = output for the `info` counts); a surface keeping its name but losing or gaining
    // a connected part is one of these.
    SurfacePartLost,
    SurfacePartCreated,
};
inline constexpr LedgerKind kLastLedgerKind = LedgerKind::SurfacePartCreated;

// snake_case name used in JSON reports ("corner_merge", ...).
std::string ledgerKindName(LedgerKind kind);

enum class EntityKind { Surface, Line, Corner, Vertex };
std::string entityKindName(EntityKind kind);

struct EntityRef {
    EntityKind kind = EntityKind::Surface;
    int id = -1;
    std::string name; // surface name, or a generated line/corner name
    bool operator==(const EntityRef &o) const { return kind == o.kind && id == o.id; }
};

struct LedgerRecord {
    LedgerKind kind = LedgerKind::CornerMerge;
    std::vector<EntityRef> inputs;  // entities of the input model involved
    std::vector<EntityRef> outputs; // entities of the output model (or output vertices)
    Vec3 position = Vec3::Zero();   // where to look
    double size = 0.0;              // distance moved, area or length (see sizeMeaning)
    std::string sizeMeaning;        // "distance", "area", "length"
    std::string note;               // one line for the reviewer: noteText.text()
    MessageText noteText;           // the same, for a translation (empty when read from a file)
    // For a lost or created entity: the index in the ledger of the simplification that caused it
    // (the nearest one within reach), or -1 when none did (an artefact of the resolution).
    int cause = -1;
};

using SimplificationLedger = std::vector<LedgerRecord>;

// References into a model with topology (names of lines and corners are generated when empty).
EntityRef surfaceRef(const Model &model, int surface);
EntityRef lineRef(const Model &model, int line);
EntityRef cornerRef(const Model &model, int corner);
EntityRef vertexRef(int vertex);

// Sets the record's note and its pattern for translations.
inline void setNote(LedgerRecord &record, MessageText text)
{
    record.note = text.text();
    record.noteText = std::move(text);
}

// Adds `ref` to `refs` unless already present (records list each entity once).
void addUnique(std::vector<EntityRef> &refs, const EntityRef &ref);

// Number of records of one kind.
int countKind(const SimplificationLedger &ledger, LedgerKind kind);

} // namespace stratamesh
