#pragma once
// The selected layer in its section plane x = const, drawn with QPainter: the blade section (CAD
// or reconstructed), the ball-centre path of the layer and the original and re-scheduled tool
// axes as short lines at a subset of its points, so the S-theta schedule is seen against the
// blade. y runs to the right and z up (looking along -x, as the 3D view's side preset).

#include "core/job/display_scene.h"

#include <QWidget>
#include <vector>

namespace bladeaxis::ui {

class SectionView final : public QWidget {
    Q_OBJECT

  public:
    explicit SectionView(QWidget* parent = nullptr);

    // Copies what the layer needs; a layer outside the scene clears the view.
    void setLayer(const job::DisplayScene& scene, int layer);
    void clearLayer();
    int layer() const { return m_layer; }

    QSize sizeHint() const override { return {480, 400}; }

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    struct Glyph {
        QPointF centre;
        QPointF original, rescheduled; // unit in-plane directions; rescheduled (0, 0) if none
    };

    QRectF pathBounds() const;
    QRectF contentBounds() const;
    double glyphLength() const; // mm

    int m_layer = -1;
    double m_sectionX = 0.0;
    double m_toolRadius = 0.0;
    QString m_surfaceName;
    std::vector<std::vector<QPointF>> m_section; // (y, z) pieces; closed ones repeat the first
    std::vector<QPointF> m_centres;              // the layer's ball-centre path, (y, z)
    std::vector<Glyph> m_glyphs;
};

} // namespace bladeaxis::ui
