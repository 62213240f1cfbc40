// What belongs to one program stays with it: a tool radius typed (or asked for) for one program is
// never applied to another, a radius that contradicts the program's is shown and blocks the
// export until resolved, the blade CAD is detached from the next program and re-checks the one on
// screen, a machine file that does not load is not used, a job refused while another runs
// changes nothing, and a saved job is a *.bladeaxis.json file. Read from the window's state.

#include "app/batch/batch_runner.h"
#include "ui/main_window.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <functional>
#include <memory>
#include <sstream>

namespace {

constexpr int kJobTimeoutMs = 240'000;

const QString kNoRadius =
    QStringLiteral(BLADEAXIS_TEST_DATA_DIR "/programs/naca_weak_3rev_no_radius.nc");
const QString kHeaderR8 = QStringLiteral(BLADEAXIS_TEST_DATA_DIR "/programs/naca_weak_3rev.nc");
const QString kCutter16x8 = QStringLiteral(BLADEAXIS_TEST_DATA_DIR "/programs/turbine_2rev.cls");
const QString kOut = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/program_settings");

// Answers the modal dialogs that open while it lives: `answer` gets each one and returns true
// once it has handled it.
class DialogAnswerer {
  public:
    explicit DialogAnswerer(std::function<bool(QWidget*)> answer) : m_answer(std::move(answer)) {
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            if (QWidget* modal = QApplication::activeModalWidget()) {
                if (m_answer(modal)) {
                    ++m_answered;
                }
            }
        });
        m_timer.start(50);
    }
    int answered() const { return m_answered; }

  private:
    std::function<bool(QWidget*)> m_answer;
    QTimer m_timer;
    int m_answered = 0;
};

bool clickButton(QWidget* modal, const QString& prefix) {
    auto* box = qobject_cast<QMessageBox*>(modal);
    if (box == nullptr) {
        return false;
    }
    for (QAbstractButton* button : box->buttons()) {
        if (button->text().startsWith(prefix)) {
            button->click();
            return true;
        }
    }
    return false;
}

} // namespace

class ProgramSettingsTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(QDir(kOut).removeRecursively() || !QDir(kOut).exists());
        QVERIFY(QDir().mkpath(kOut));
        m_window = std::make_unique<bladeaxis::ui::MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        setComparing(false); // faster jobs: the comparison is not what is tested
    }

    void theToolRadiusBoxStartsFromFileAndNothingIsRemembered() {
        QVERIFY(!m_window->toolRadiusBox()->isEnabled()); // no program: nothing to type for
        QCOMPARE(m_window->toolRadiusBox()->value(), 0.0);
        QVERIFY(!QSettings().contains(QStringLiteral("job/toolRadius")));
    }

    void aProgramWithoutARadiusAsksWithAnEmptyPromptAndTheAnswerIsShownAsTyped() {
        double prefilled = -1.0;
        DialogAnswerer answerer([&prefilled](QWidget* modal) {
            auto* dialog = qobject_cast<QInputDialog*>(modal);
            if (dialog == nullptr) {
                return false;
            }
            prefilled = dialog->doubleValue();
            dialog->setDoubleValue(4.0);
            dialog->accept();
            return true;
        });
        QVERIFY(runAndWait([&] { m_window->runProgram(kNoRadius); }, 2));
        QCOMPARE(prefilled, 0.0);
        QCOMPARE(*m_window->result()->toolRadius, 4.0);
        QCOMPARE(m_window->toolRadiusBox()->value(), 4.0);
        QVERIFY2(sourceText().contains(QStringLiteral("typed")), qPrintable(sourceText()));
        QVERIFY(!QSettings().contains(QStringLiteral("job/toolRadius")));
    }

    // The blocker: a radius given for one program silently re-scheduled the next one, which
    // states its own, with it.
    void aProgramStatingR8AfterTyping4ForAnotherUsesR8() {
        QCOMPARE(*m_window->result()->toolRadius, 4.0); // typed for the previous program
        QVERIFY(runAndWait([&] { m_window->runProgram(kHeaderR8); }));
        QCOMPARE(*m_window->result()->toolRadius, 8.0);
        QVERIFY(!m_window->spec().toolRadius.has_value());
        QCOMPARE(m_window->toolRadiusBox()->value(), 0.0); // "from file"
        QVERIFY2(sourceText().contains(QStringLiteral("from the program (header comment)")),
                 qPrintable(sourceText()));
        QVERIFY(!m_window->radiusConflictBanner()->isVisible());
        QVERIFY(!m_window->radiusConflictUnresolved());
    }

    void aCutterStatementIsUsedAndNamedAsTheSource() {
        m_window->toolRadiusBox()->setValue(4.0);
        emit m_window->toolRadiusBox()->editingFinished(); // 4 for the program on screen only
        QVERIFY(waitForJob());
        QCOMPARE(*m_window->result()->toolRadius, 4.0);
        QVERIFY(runAndWait([&] { m_window->runProgram(kCutter16x8); }));
        QCOMPARE(*m_window->result()->toolRadius, 8.0);
        QVERIFY2(sourceText().contains(QStringLiteral("CUTTER")), qPrintable(sourceText()));
        QVERIFY(!m_window->radiusConflictUnresolved());
    }

    void aRadiusTypedForAnotherProgramNeverPrefillsThePrompt() {
        m_window->toolRadiusBox()->setValue(5.5);
        emit m_window->toolRadiusBox()->editingFinished();
        QVERIFY(waitForJob());
        double prefilled = -1.0;
        DialogAnswerer answerer([&prefilled](QWidget* modal) {
            auto* dialog = qobject_cast<QInputDialog*>(modal);
            if (dialog == nullptr) {
                return false;
            }
            prefilled = dialog->doubleValue();
            dialog->reject();
            return true;
        });
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runProgram(kNoRadius);
        QVERIFY(finished.wait(kJobTimeoutMs));
        QTRY_VERIFY_WITH_TIMEOUT(answerer.answered() == 1, 10'000);
        QCOMPARE(prefilled, 0.0);
        QVERIFY(m_window->spec().program.string().ends_with("turbine_2rev.cls")); // still shown
    }

    void aTypedRadiusThatContradictsTheProgramIsAVisibleConflictThatBlocksExport() {
        QVERIFY(runAndWait([&] { m_window->runProgram(kHeaderR8); }));
        m_window->toolRadiusBox()->setValue(4.0);
        emit m_window->toolRadiusBox()->editingFinished();
        QVERIFY(waitForJob());
        QCOMPARE(*m_window->result()->toolRadius, 4.0);
        QVERIFY(m_window->radiusConflictUnresolved());
        QVERIFY(m_window->radiusConflictBanner()->isVisible());
        const QString banner = bannerText();
        QVERIFY2(banner.contains(QStringLiteral("4 mm")) && banner.contains(QStringLiteral("8 mm")),
                 qPrintable(banner));
        QVERIFY2(sourceText().contains(QStringLiteral("conflicts")), qPrintable(sourceText()));

        const QString output = kOut + QStringLiteral("/conflict.nc");
        const bladeaxis::Status refused = m_window->exportProgram(output);
        QVERIFY(!refused.has_value());
        QVERIFY(!m_window->exportClData(kOut + QStringLiteral("/conflict.cl")).has_value());
        QVERIFY(!QFileInfo::exists(output));

        // The export dialog asks; Cancel writes nothing and keeps the conflict.
        {
            DialogAnswerer cancel([](QWidget* modal) {
                auto* box = qobject_cast<QMessageBox*>(modal);
                if (box == nullptr ||
                    box->windowTitle() != QStringLiteral("Tool radius conflict")) {
                    return false;
                }
                box->button(QMessageBox::Cancel)->click();
                return true;
            });
            m_window->exportProgramTo(output);
            QCOMPARE(cancel.answered(), 1);
        }
        QVERIFY(!QFileInfo::exists(output));
        QVERIFY(m_window->radiusConflictUnresolved());

        // "Export with 4 mm" keeps the typed radius for this program, as --tool-radius does.
        {
            DialogAnswerer keep(
                [](QWidget* modal) { return clickButton(modal, QStringLiteral("Export with 4")); });
            m_window->exportProgramTo(output);
            QCOMPARE(keep.answered(), 1);
        }
        QVERIFY(QFileInfo::exists(output));
        QVERIFY(!m_window->radiusConflictUnresolved());
        QVERIFY(!m_window->radiusConflictBanner()->isVisible());
        QVERIFY2(sourceText().contains(QStringLiteral("kept over the program's 8")),
                 qPrintable(sourceText()));
    }

    void theConflictBannerReRunsWithTheProgramsRadius() {
        m_window->toolRadiusBox()->setValue(3.0);
        emit m_window->toolRadiusBox()->editingFinished();
        QVERIFY(waitForJob());
        QVERIFY(m_window->radiusConflictBanner()->isVisible()); // a new value: asked again
        auto* useProgram =
            m_window->radiusConflictBanner()->findChild<QPushButton*>("useProgramRadius");
        QVERIFY(useProgram != nullptr);
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        useProgram->click();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(*m_window->result()->toolRadius, 8.0);
        QVERIFY(!m_window->spec().toolRadius.has_value());
        QVERIFY(!m_window->radiusConflictBanner()->isVisible());
        QCOMPARE(m_window->toolRadiusBox()->value(), 0.0);
    }

    void loadingBladeCadReChecksTheProgramOnScreenAndItCanBeCleared() {
        QVERIFY(runAndWait([&] { m_window->runDemo(); }));
        const QString folder = kOut + QStringLiteral("/demo");
        QVERIFY(m_window->exportReport(folder).has_value());
        const QString step = folder + QStringLiteral("/demo_blade.step");
        const QString program = folder + QStringLiteral("/demo_blade.nc");
        QVERIFY(QFileInfo::exists(step) && QFileInfo::exists(program));
        QVERIFY(runAndWait([&] { m_window->runProgram(program); }));
        QVERIFY(!m_window->result()->cadCheck.has_value());
        QVERIFY(!m_window->clearCadAction()->isEnabled());

        QVERIFY(runAndWait([&] { m_window->setBladeCad(step); }));
        QVERIFY(m_window->result()->cadCheck.has_value()); // checked at once, not next time
        QCOMPARE(m_window->bladeCadPath(), step);
        QVERIFY(m_window->clearCadAction()->isEnabled());

        QVERIFY(runAndWait([&] { m_window->clearCadAction()->trigger(); }));
        QVERIFY(!m_window->result()->cadCheck.has_value());
        QVERIFY(m_window->bladeCadPath().isEmpty());
        QVERIFY(m_window->spec().cad.file.empty());
        QVERIFY(!m_window->clearCadAction()->isEnabled());
    }

    void openingAnotherProgramDetachesTheBladeCad() {
        const QString folder = kOut + QStringLiteral("/demo");
        QVERIFY(runAndWait([&] { m_window->setBladeCad(folder + "/demo_blade.step"); }));
        QVERIFY(m_window->result()->cadCheck.has_value());
        QVERIFY(runAndWait([&] { m_window->runProgram(kHeaderR8); }));
        QVERIFY(m_window->bladeCadPath().isEmpty());
        QVERIFY(m_window->spec().cad.file.empty());
        QVERIFY(!m_window->result()->cadCheck.has_value());
    }

    void aMachineFileThatDoesNotLoadIsRefusedAndNotUsed() {
        const QString bad = kOut + QStringLiteral("/bad_machine.json");
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\"schema\": \"bladeaxis-machine/1\", \"kinematics\": 3}");
        file.close();
        const bladeaxis::Status set = m_window->setMachineFile(bad);
        QVERIFY(!set.has_value());
        QVERIFY(QSettings().value(QStringLiteral("job/machine")).toString() != bad);
        QVERIFY(runAndWait([&] { m_window->runProgram(kHeaderR8); }));
        QVERIFY(m_window->spec().machineFile.empty()); // the built-in machine, not the bad file
        bladeaxis::ui::MainWindow fresh;               // nor in the next session
        QVERIFY(fresh.spec().machineFile.empty());
    }

    void aNewJobRefusedWhileOneRunsChangesNothing() {
        // A long job (30 revolutions, compared with the optimum), so that it still runs while
        // the dialogs are answered.
        const QString longProgram = kOut + QStringLiteral("/long.nc");
        std::ostringstream out, err;
        QCOMPARE(bladeaxis::app::runBatchCommandLine({"bladeaxis", "--batch", "--generate",
                                                      longProgram.toStdString(), "--revolutions",
                                                      "30", "--pitch", "0.5", "-q"},
                                                     out, err),
                 0);
        setComparing(true);
        m_window->runProgram(longProgram);
        setComparing(false);
        QVERIFY(m_window->isRunning());
        m_window->undoStack()->push(new QUndoCommand(QStringLiteral("an edit")));
        QVERIFY(m_window->isWindowModified());
        // Programmatic: refused, history kept.
        m_window->runDemo();
        QCOMPARE(m_window->undoStack()->count(), 1);
        QVERIFY(!m_window->spec().demo);
        // The menu: Discard the edits, then keep the running job: nothing changes.
        {
            DialogAnswerer answer([](QWidget* modal) {
                return clickButton(modal, QStringLiteral("Discard")) ||
                       clickButton(modal, QStringLiteral("Keep it running"));
            });
            runDemoAction()->trigger();
            QCOMPARE(answer.answered(), 2);
        }
        QCOMPARE(m_window->undoStack()->count(), 1);
        QVERIFY(m_window->isWindowModified());
        QVERIFY(!m_window->spec().demo);
        if (!m_window->isRunning()) { // it ended while the dialogs were answered: one more
            setComparing(true);
            m_window->runProgram(longProgram);
            setComparing(false);
            m_window->undoStack()->push(new QUndoCommand(QStringLiteral("an edit")));
        }
        // Discard, then cancel the running job: the demo runs.
        {
            DialogAnswerer answer([](QWidget* modal) {
                return clickButton(modal, QStringLiteral("Discard")) ||
                       clickButton(modal, QStringLiteral("Cancel the running job"));
            });
            runDemoAction()->trigger();
            QCOMPARE(answer.answered(), 2);
        }
        QVERIFY(m_window->spec().demo);
        QCOMPARE(m_window->undoStack()->count(), 0);
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->isRunning(), kJobTimeoutMs);
        QVERIFY(m_window->result().has_value());
        QVERIFY(m_window->spec().demo);
    }

    void savingAJobWritesABladeaxisJsonFileAndNeedsAJob() {
        bladeaxis::ui::MainWindow fresh;
        QVERIFY(!fresh.saveJobAction()->isEnabled());
        QVERIFY(!fresh.saveJob(kOut + QStringLiteral("/nothing")).has_value());
        QVERIFY(!QFileInfo::exists(kOut + QStringLiteral("/nothing.bladeaxis.json")));
        QVERIFY(m_window->saveJobAction()->isEnabled());
        QVERIFY(m_window->saveJob(kOut + QStringLiteral("/blade")).has_value());
        QVERIFY(QFileInfo::exists(kOut + QStringLiteral("/blade.bladeaxis.json")));
        QVERIFY(m_window->saveJob(kOut + QStringLiteral("/other.json")).has_value());
        QVERIFY(QFileInfo::exists(kOut + QStringLiteral("/other.bladeaxis.json")));
        QCOMPARE(bladeaxis::ui::MainWindow::jobFilePath(QStringLiteral("x.bladeaxis.json")),
                 QStringLiteral("x.bladeaxis.json"));
    }

  private:
    QString sourceText() const { return m_window->toolRadiusSourceLabel()->text(); }

    QString bannerText() const {
        QString text;
        for (const QLabel* label : m_window->radiusConflictBanner()->findChildren<QLabel*>()) {
            text += label->text();
        }
        return text;
    }

    void setComparing(bool on) const {
        for (QAction* action : m_window->findChildren<QAction*>()) {
            if (action->text() == QStringLiteral("&Compare methods") ||
                action->text() == QStringLiteral("Compare with the &optimum")) {
                action->setChecked(on);
            }
        }
    }

    QAction* runDemoAction() const {
        for (QAction* action : m_window->findChildren<QAction*>()) {
            if (action->text() == QStringLiteral("Run &demo")) {
                return action;
            }
        }
        return nullptr;
    }

    // Runs `start` and waits for `jobs` jobs to finish; true when the last one succeeded.
    bool runAndWait(const std::function<void()>& start, int jobs = 1) {
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        start();
        while (finished.size() < jobs) {
            if (!finished.wait(kJobTimeoutMs)) {
                return false;
            }
        }
        return finished.back().front().toBool();
    }

    bool waitForJob() {
        if (!m_window->isRunning()) {
            return false;
        }
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        return finished.wait(kJobTimeoutMs) && finished.back().front().toBool();
    }

    std::unique_ptr<bladeaxis::ui::MainWindow> m_window;
};

QTEST_MAIN(ProgramSettingsTest)
#include "program_settings_test.moc"
