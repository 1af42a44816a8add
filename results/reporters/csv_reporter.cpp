// csv: each table as <id>.csv, every value at full precision, for other tools.
#include "results/reporters/reporter.hpp"
#include "results/text/csv_table.hpp"

namespace mhb {

namespace {

class CsvTables final : public TableFormatReporter {
public:
    std::string_view name() const override { return "csv"; }
    std::string_view description() const override {
        return "CSV: each table as <id>.csv, every value at full precision";
    }
    bool selected_by_default() const override { return true; }
    std::string render(const Table& table) const override { return render_csv(table); }
};

} // namespace

std::unique_ptr<Reporter> csv_tables_reporter() {
    return std::make_unique<CsvTables>();
}

} // namespace mhb
