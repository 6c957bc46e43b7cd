// ModelScene converts a model into actors: one per surface, box hidden by default, colours by
// feature type, and a legend that counts what is there.
#include "widgets/scene_test_model.h"

#include "feature_palette.h"
#include "model_scene.h"

#include <QtTest>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

using namespace stratamesh;

namespace {
int hueDistance(const QColor &a, const QColor &b)
{
    const int d = std::abs(a.hsvHue() - b.hsvHue()) % 360;
    return std::min(d, 360 - d);
}
} // namespace

class TestModelScene : public QObject {
    Q_OBJECT
private slots:
    void oneActorPerSurfaceAndBoxHidden()
    {
        vtkNew<vtkRenderer> renderer;
        ModelScene scene(renderer);
        const auto model = std::make_shared<const Model>(test::sceneTestModel());
        scene.setModel(model);
        QCOMPARE(scene.surfaceActorCount(), int(model->surfaces.size()));
        QCOMPARE(scene.visibleSurfaceActorCount(), 2); // horizon + fault; 6 box faces hidden
        QVERIFY(!scene.boxVisible());
        scene.setBoxVisible(true);
        QCOMPARE(scene.visibleSurfaceActorCount(), 8);
        scene.setBoxVisible(false);
        QCOMPARE(scene.visibleSurfaceActorCount(), 2);
        // Surface actors carry exactly the model's triangles.
        vtkActorCollection *actors = renderer->GetActors();
        actors->InitTraversal();
        vtkIdType triangles = 0;
        for (int i = 0; i < actors->GetNumberOfItems(); ++i) {
            auto *data = vtkPolyData::SafeDownCast(actors->GetNextActor()->GetMapper()->GetInput());
            triangles += data->GetNumberOfPolys();
        }
        QCOMPARE(std::size_t(triangles), model->triangleCount());
    }

    void linesAndCornersComeFromTheModel()
    {
        vtkNew<vtkRenderer> renderer;
        ModelScene scene(renderer);
        const auto model = std::make_shared<const Model>(test::sceneTestModel());
        QVERIFY(!model->lines.empty());
        scene.setModel(model);
        QCOMPARE(scene.lineCount(), int(model->lines.size()));
        QCOMPARE(scene.cornerCount(), int(model->corners.size()));
    }

    void coloursFollowFeatureTypes()
    {
        vtkNew<vtkRenderer> renderer;
        ModelScene scene(renderer);
        Model model = test::sceneTestModel();
        // A second horizon patch of the same feature, and a second horizon feature.
        Surface patch = model.surfaces[0];
        patch.name = "horizon_2";
        model.surfaces.push_back(patch);
        Surface other = model.surfaces[0];
        other.name = other.featureName = "other_horizon";
        model.surfaces.push_back(other);
        scene.setModel(std::make_shared<const Model>(model));
        const auto &colors = scene.surfaceColors();
        QCOMPARE(colors.size(), model.surfaces.size());
        const QColor horizon = colors[0], fault = colors[1], patch2 = colors[8],
                     otherHorizon = colors[9];
        QVERIFY(hueDistance(horizon, fault) > 40);      // types look different
        QVERIFY(horizon != patch2);                     // patches of one feature are told apart ...
        QVERIFY(hueDistance(horizon, patch2) <= 3);     // ... but keep the feature's hue
        QVERIFY(horizon != otherHorizon);               // two features differ
        QVERIFY(hueDistance(otherHorizon, fault) > 40); // and remain horizon-like
    }

    void legendCountsTypesAndFeatures()
    {
        vtkNew<vtkRenderer> renderer;
        ModelScene scene(renderer);
        scene.setModel(std::make_shared<const Model>(test::sceneTestModel()));
        const auto &legend = scene.legend();
        QCOMPARE(int(legend.size()), 3);
        QCOMPARE(legend[0].type, FeatureType::Horizon);
        QCOMPARE(legend[0].surfaceCount, 1);
        QCOMPARE(legend[0].featureNames, QStringList{QStringLiteral("horizon")});
        QCOMPARE(legend[1].type, FeatureType::Fault);
        QCOMPARE(legend.back().type, FeatureType::Boundary);
        QCOMPARE(legend.back().surfaceCount, 6);
        QCOMPARE(legend[0].color, featureTypeColor(FeatureType::Horizon));
    }

    void replacingAndClearingRemovesActors()
    {
        vtkNew<vtkRenderer> renderer;
        ModelScene scene(renderer);
        scene.setModel(std::make_shared<const Model>(test::sceneTestModel()));
        const int afterFirst = renderer->GetActors()->GetNumberOfItems();
        QVERIFY(afterFirst >= 8);
        scene.setModel(std::make_shared<const Model>(test::sceneTestModel()));
        QCOMPARE(renderer->GetActors()->GetNumberOfItems(), afterFirst);
        scene.setModel(nullptr);
        QCOMPARE(renderer->GetActors()->GetNumberOfItems(), 0);
        QVERIFY(scene.legend().empty());
    }

    void badIndicesAreSkippedNotFatal()
    {
        vtkNew<vtkRenderer> renderer;
        ModelScene scene(renderer);
        Model model = test::sceneTestModel();
        model.surfaces[0].triangles.push_back({0, 1, 100000});
        model.lines.push_back(Line{"broken", {-1, 5, 999999}, false, {-1, -1}, {0}});
        scene.setModel(std::make_shared<const Model>(model));
        QCOMPARE(scene.surfaceActorCount(), int(model.surfaces.size()));
        QCOMPARE(scene.lineCount(), int(model.lines.size()) - 1);
    }
};

QTEST_GUILESS_MAIN(TestModelScene)
#include "test_model_scene.moc"
