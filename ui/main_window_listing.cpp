// The main window's NC listing (issue 38): the program's text in a dock beside the pages,
// cross-probed with the 3D view, the tool slider and the layer table: a block selects its
// record everywhere, and a record selected anywhere scrolls the listing to its block.

#include "ui/main_window.h"
#include "ui/nc_listing.h"
#include "ui/toolpath_view.h"

#include <QAction>
#include <QDockWidget>
#include <QSlider>

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
}

void MainWindow::showListing(std::string programText, bool newProgram) {
    if (newProgram) {
        m_selectedRecord.reset();
    }
    m_listing->setSource(NcListing::sourceOf(*m_result, std::move(programText)));
    if (m_selectedRecord) {
        m_listing->selectRecord(*m_selectedRecord);
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
    m_selectedRecord = record;
    m_listing->selectRecord(record);
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
        m_selectedRecord = m_result->pass.first + passIndex;
        m_listing->selectRecord(*m_selectedRecord);
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
