// The main window after the demo job, at a small laptop screen (1366x768) and a large one
// (2560x1440), in the light and the dark palette: a screenshot of each, and what Qt can tell
// about text a person cannot read there: a label or button narrower than its text (cut off),
// and a widget placed outside its parent (not shown at all).

#include "ui/main_window.h"

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>
#include <QTextDocument>
#include <QToolBar>
#include <memory>

namespace {

constexpr int kJobTimeoutMs = 240'000;

// A widget inside a scrolling area may lie outside its viewport on purpose (scrolled away), and
// a tool bar moves what does not fit into its extension menu: neither is a layout fault.
bool mayLieOutside(const QWidget* widget) {
    for (const QWidget* ancestor = widget->parentWidget(); ancestor != nullptr;
         ancestor = ancestor->parentWidget()) {
        if (qobject_cast<const QAbstractScrollArea*>(ancestor) != nullptr ||
            qobject_cast<const QToolBar*>(ancestor) != nullptr) {
            return true;
        }
    }
    return false;
}

// The width the widest line of a label's text needs (rich text measured as a document).
int textWidth(const QLabel& label) {
    if (Qt::mightBeRichText(label.text())) {
        QTextDocument document;
        document.setDefaultFont(label.font());
        document.setHtml(label.text());
        return static_cast<int>(document.idealWidth());
    }
    int widest = 0;
    for (const QString& line : label.text().split(QLatin1Char('\n'))) {
        widest = std::max(widest, label.fontMetrics().horizontalAdvance(line));
    }
    return widest;
}

QString describe(const QWidget* widget) {
    return QStringLiteral("%1 '%2'").arg(QString::fromLatin1(widget->metaObject()->className()),
                                         widget->objectName());
}

// Every fault found on the visible widgets of `window`.
QStringList layoutFaults(const QWidget& window) {
    QStringList faults;
    for (const QWidget* widget : window.findChildren<QWidget*>()) {
        if (!widget->isVisibleTo(&window) || widget->width() <= 0) {
            continue;
        }
        const QWidget* parent = widget->parentWidget();
        if (parent != nullptr && !mayLieOutside(widget) && !widget->isWindow() &&
            !parent->rect().contains(widget->geometry())) {
            faults << QStringLiteral("%1 lies outside its parent (%2 in %3x%4)")
                          .arg(describe(widget))
                          .arg(QStringLiteral("%1,%2 %3x%4")
                                   .arg(widget->x())
                                   .arg(widget->y())
                                   .arg(widget->width())
                                   .arg(widget->height()))
                          .arg(parent->width())
                          .arg(parent->height());
        }
        if (const auto* label = qobject_cast<const QLabel*>(widget);
            label != nullptr && !label->wordWrap() && !label->text().isEmpty() &&
            label->pixmap().isNull() && textWidth(*label) > label->contentsRect().width() + 1) {
            faults << QStringLiteral("%1 cuts its text '%2' (%3 px wide, needs %4)")
                          .arg(describe(label), label->text().left(40))
                          .arg(label->contentsRect().width())
                          .arg(textWidth(*label));
        }
        if (const auto* button = qobject_cast<const QAbstractButton*>(widget);
            button != nullptr && !button->text().isEmpty() && !mayLieOutside(button) &&
            button->sizeHint().width() > button->width() + 1) {
            faults << QStringLiteral("%1 cuts its text '%2' (%3 px wide, needs %4)")
                          .arg(describe(button), button->text())
                          .arg(button->width())
                          .arg(button->sizeHint().width());
        }
    }
    return faults;
}

} // namespace

class LayoutCheckTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        m_window = std::make_unique<bladeaxis::ui::MainWindow>();
        m_window->resize(1366, 768);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runDemo();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        m_window->selectLayer(m_window->layerTable()->rowCount() / 2);
    }

    // The check itself: it must see a label too narrow for its text and a child placed past its
    // parent's edge, or its silence above would mean nothing.
    void theCheckFindsACutLabelAndAMisplacedWidget() {
        QWidget parent;
        parent.resize(200, 100);
        auto* cut = new QLabel(QStringLiteral("A label far too long for its width"), &parent);
        cut->setGeometry(0, 0, 40, 20);
        auto* outside = new QCheckBox(QStringLiteral("x"), &parent);
        outside->setGeometry(190, 90, 60, 30);
        parent.show();
        QVERIFY(QTest::qWaitForWindowExposed(&parent));
        const QStringList faults = layoutFaults(parent);
        QVERIFY2(faults.size() >= 2, qPrintable(faults.join(QLatin1Char('\n'))));
        QVERIFY(faults.filter(QStringLiteral("cuts its text")).size() >= 1);
        QVERIFY(faults.filter(QStringLiteral("outside its parent")).size() >= 1);
    }

    void nothingIsCutOffOrMisplaced_data() {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::addColumn<bool>("dark");
        for (const auto& [w, h] : {std::pair{1366, 768}, std::pair{2560, 1440}}) {
            for (const bool dark : {false, true}) {
                const QString name =
                    QStringLiteral("%1x%2 %3").arg(w).arg(h).arg(dark ? "dark" : "light");
                QTest::newRow(qPrintable(name)) << w << h << dark;
            }
        }
    }

    void nothingIsCutOffOrMisplaced() {
        QFETCH(int, width);
        QFETCH(int, height);
        QFETCH(bool, dark);
        m_window->setDarkPalette(dark);
        m_window->resize(width, height);
        QTest::qWait(200); // layouts and the 3D view settle
        QApplication::processEvents();
        const QImage shot = m_window->grab().toImage();
        QVERIFY(shot.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/layout_%1x%2_%3.png")
                              .arg(width)
                              .arg(height)
                              .arg(dark ? "dark" : "light")));
        const QStringList faults = layoutFaults(*m_window);
        QVERIFY2(faults.isEmpty(), qPrintable(faults.join(QLatin1Char('\n'))));
    }

    void cleanupTestCase() { m_window->setDarkPalette(false); }

  private:
    std::unique_ptr<bladeaxis::ui::MainWindow> m_window;
};

QTEST_MAIN(LayoutCheckTest)
#include "layout_check_test.moc"
