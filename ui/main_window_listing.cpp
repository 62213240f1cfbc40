// The main window's NC listing (issue 38): the program's text in a dock beside the pages,
// cross-probed with the 3D view, the tool slider, the layer table and the axis plots: a block
// selects its record everywhere, and a record selected anywhere scrolls the listing to its block.

#include "ui/main_window.h"
#include "ui/nc_listing.h"
#include "ui/profile_plots.h"
#include "ui/toolpath_view.h"

#include <QAction>
#include <QDockWidget>
#include <QSlider>
#include <algorithm>

namespace bladeaxis::ui {

void MainWindow::buildListingDock() {
    m_listingDock = new QDockWidget(tr("NC listing"), this);
    m_listingDock->setObjectName(QStringLiteral("listingDock"));
    m_listing = new NcListing(m_listingDock);
    m_listing->setObjectName(QStringLiteral("ncListing"));
    m_listingDock->setWidget(m_listing);
    addDockWidget(Qt::RightDockWidgetArea, m_listingDock);
    m_listingDock->toggleViewAction()->setObjectName(QStringLiteral("showListing"));
    m_listingDock->toggleViewAction()->setShortcut(QKeySequence(tr("Ctrl+L")));
    connect(m_listing, &NcListing::recordSelected, this, &MainWindow::selectRecord);
    connect(m_plots, &ProfilePlots::timeClicked, this, &MainWindow::selectPlottedTime);
}

void MainWindow::showListing(std::string programText, bool newProgram) {
    if (newProgram) {
        m_selectedRecord.reset();
        m_plots->setMarkedTime(std::nullopt);
    }
    m_listing->setSource(NcListing::sourceOf(*m_result, std::move(programText)));
    if (m_selectedRecord) { // a re-run for an edit: the new program's times
        markSelectedRecord(*m_selectedRecord);
    }
}

std::optional<std::size_t> MainWindow::passIndexOf(std::size_t record) const {
    if (!m_result || record < m_result->pass.first ||
        record - m_result->pass.first >= m_result->pass.count) {
        return std::nullopt;
    }
    return record - m_result->pass.first;
}

void MainWindow::selectRecord(std::size_t record) {
    if (!m_result || record >= m_result->program.path().records.size()) {
        return;
    }
    markSelectedRecord(record);
    // Approach, retract and rapid blocks are not drawn: only the listing shows them.
    if (const std::optional<std::size_t> passIndex = passIndexOf(record)) {
        selectLayer(m_view3d->layerOfRecord(*passIndex));
        const QSignalBlocker block(m_toolSlider); // the tool is shown below, also at value 0
        m_toolSlider->setValue(static_cast<int>(*passIndex));
        m_view3d->showToolAt(*passIndex);
    }
}

void MainWindow::showPassRecord(std::size_t passIndex) {
    m_view3d->showToolAt(passIndex);
    if (m_result && passIndex < m_result->pass.count) {
        markSelectedRecord(m_result->pass.first + passIndex);
    }
}

void MainWindow::markSelectedRecord(std::size_t record) {
    m_selectedRecord = record;
    m_listing->selectRecord(record);
    const std::optional<std::size_t> passIndex = passIndexOf(record);
    m_plots->setMarkedTime(passIndex ? timeOfPassRecord(plottedProfile(), *passIndex)
                                     : std::nullopt);
}

const analysis::AxisProfile& MainWindow::plottedProfile() const {
    return m_result->rescheduled ? m_result->rescheduled->profile : m_result->original;
}

std::optional<double> MainWindow::timeOfPassRecord(const analysis::AxisProfile& profile,
                                                   std::size_t passIndex) {
    const auto& records = profile.sampleRecord;
    const auto it = std::lower_bound(records.begin(), records.end(), passIndex);
    if (it == records.end()) {
        return std::nullopt; // not analysed (a job that released its samples)
    }
    return profile.timeAt(static_cast<std::size_t>(it - records.begin()));
}

std::optional<std::size_t> MainWindow::passRecordAtTime(const analysis::AxisProfile& profile,
                                                        double seconds) {
    const std::size_t samples = profile.sampleRecord.size();
    if (samples == 0) {
        return std::nullopt;
    }
    // Sample times ascend: the first sample at or after `seconds`, or the one before when nearer.
    std::size_t low = 0, high = samples;
    while (low < high) {
        const std::size_t middle = low + (high - low) / 2;
        if (profile.timeAt(middle) < seconds) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    if (low == samples ||
        (low > 0 && seconds - profile.timeAt(low - 1) < profile.timeAt(low) - seconds)) {
        --low;
    }
    return profile.sampleRecord[low];
}

void MainWindow::selectPlottedTime(double seconds) {
    if (!m_result) {
        return;
    }
    if (const std::optional<std::size_t> passIndex = passRecordAtTime(plottedProfile(), seconds)) {
        selectRecord(m_result->pass.first + *passIndex);
    }
}

void MainWindow::showLayerInListing(std::size_t first, std::size_t last) {
    const std::optional<std::size_t> shown = m_listing->currentRecord();
    const std::optional<std::size_t> passIndex = shown ? passIndexOf(*shown) : std::nullopt;
    // A block of the layer selected it (or is selected already): it stays.
    if (passIndex && *passIndex >= first && *passIndex <= last) {
        return;
    }
    m_listing->selectRecord(m_result->pass.first + first);
}

} // namespace bladeaxis::ui
