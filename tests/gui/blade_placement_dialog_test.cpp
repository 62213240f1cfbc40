// The blade-CAD placement dialog: it shows a placement in degrees and mm and returns what its
// fields say in rad and mm, the rotation about X, Y and Z like --cad-rotate-deg.

#include "ui/blade_placement_dialog.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QTest>
#include <cmath>

namespace {

// Not core/base/units.h: moc parses this file and fails on <numbers>, which that header needs.
constexpr double kPi = 3.14159265358979323846;

constexpr double degToRad(double degrees) {
    return degrees * kPi / 180.0;
}

} // namespace

class BladePlacementDialogTest final : public QObject {
    Q_OBJECT

  private slots:
    void showsTheCurrentPlacementInDegreesAndMillimetres() {
        bladeaxis::cad::AxisRotationPlacement current;
        current.rotationXyz = {degToRad(90.0), 0.0, degToRad(-15.0)};
        current.translation = {1.5, -2.0, 0.25};
        const bladeaxis::ui::BladePlacementDialog dialog(current);
        QCOMPARE(dialog.rotationField(0)->value(), 90.0);
        QCOMPARE(dialog.rotationField(1)->value(), 0.0);
        QCOMPARE(dialog.rotationField(2)->value(), -15.0);
        QCOMPARE(dialog.translationField(0)->value(), 1.5);
        QCOMPARE(dialog.translationField(1)->value(), -2.0);
        QCOMPARE(dialog.translationField(2)->value(), 0.25);
    }

    void typedValuesBecomeThePlacementInRadians() {
        bladeaxis::ui::BladePlacementDialog dialog({});
        dialog.show();
        typeInto(dialog.rotationField(0), "30");
        typeInto(dialog.rotationField(1), "-45.5");
        typeInto(dialog.translationField(2), "12.75");
        const bladeaxis::cad::AxisRotationPlacement placement = dialog.placement();
        QVERIFY(std::abs(placement.rotationXyz.x() - degToRad(30.0)) < 1e-12);
        QVERIFY(std::abs(placement.rotationXyz.y() - degToRad(-45.5)) < 1e-12);
        QCOMPARE(placement.rotationXyz.z(), 0.0);
        QCOMPARE(placement.translation.x(), 0.0);
        QCOMPARE(placement.translation.z(), 12.75);
    }

    void okAcceptsAndCancelRejects() {
        bladeaxis::ui::BladePlacementDialog dialog({});
        auto* buttons = dialog.findChild<QDialogButtonBox*>();
        QVERIFY(buttons != nullptr);
        dialog.show();
        QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        dialog.show();
        QTest::mouseClick(buttons->button(QDialogButtonBox::Cancel), Qt::LeftButton);
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
    }

  private:
    // As a user types: select the field's text and type over it; interpretText commits it the
    // way leaving the field does (Enter would press the dialog's default button).
    static void typeInto(QDoubleSpinBox* field, const QString& text) {
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, text);
        field->interpretText();
    }
};

QTEST_MAIN(BladePlacementDialogTest)
#include "blade_placement_dialog_test.moc"
