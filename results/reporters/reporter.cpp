#include "results/reporters/reporter.hpp"

#include "results/store/csv.hpp"

namespace mhb {

void TableFormatReporter::write_tables(const BudgetReportContext& budget) const {
    for (const Table& table : budget.tables)
        write_file_atomically(budget.directory / (table.id + "." + std::string(name())), render(table));
}

} // namespace mhb
