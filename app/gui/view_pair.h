// The input and the output of a workflow side by side, looking through one shared camera: moving
// either view moves both, so the same place is compared. The output pane and the titles show only
// once there is an output.
#pragma once

#include <QSplitter>

class QLabel;

namespace stratamesh {

class VtkViewWidget;

class ViewPair : public QSplitter {
    Q_OBJECT
public:
    explicit ViewPair(QWidget *parent = nullptr);

    VtkViewWidget *inputView() const { return m_input; }
    VtkViewWidget *outputView() const { return m_output; }

    void setOutputShown(bool shown);
    void setTitles(const QString &input, const QString &output);
    // Half the width each, for the pane just shown.
    void splitEvenly();
    // Both views' vertical exaggeration (VtkViewWidget); the shared camera keeps looking at the
    // same place of the model.
    void setVerticalExaggeration(double factor);
    // Linked (the default): both views look through one camera. Unlinked, the output view gets
    // its own copy, moved on its own; linking again gives it the input view's camera.
    void setCamerasLinked(bool linked);
    bool camerasLinked() const;
    double verticalExaggeration() const;

private:
    VtkViewWidget *m_input = nullptr;
    VtkViewWidget *m_output = nullptr;
    QLabel *m_inputTitle = nullptr;
    QLabel *m_outputTitle = nullptr;
    QWidget *m_outputPane = nullptr;
};

} // namespace stratamesh
