// `mhbench eval --problem SPEC --points FILE`: prints f at each point of FILE, one value a line,
// at full precision (the shortest text that reads back to the same double), so that anyone can
// check a function by hand against another implementation.
#include <boost/program_options.hpp>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/problem_registry.hpp"
#include "runner/cli/command.hpp"
#include "runner/cli/parse_command_line.hpp"
#include "runner/plugins/components.hpp"
#include "runner/single_problem/points_reader.hpp"

namespace mhb::cli {
int run_eval_command(const std::vector<std::string>& args) {
    namespace po = boost::program_options;
    po::options_description options("mhbench eval: f at given points, one value a line at full precision\n\n"
                                    "Usage: mhbench eval --problem SPEC --points FILE\n\nOptions");
    options.add_options()("help,h", "this text")(
        "problem", po::value<std::string>()->required(),
        "the problem, e.g. rastrigin:dim=2,shift=1,instance=3 or bbob:f=15,dim=10,instance=2 "
        "(mhbench list problems shows them all)")(
        "points", po::value<std::string>()->required(),
        "file of points, one a line, coordinates separated by spaces or commas ('-' reads standard input); "
        "blank lines and lines starting with # are skipped. Points are evaluated as given, outside the box "
        "too "
        "(no bound repair)")(
        "plugin", po::value<std::vector<std::string>>()->composing(),
        "load this plug-in module first, so that --problem may name its problems (repeatable)");
    po::variables_map vm;
    if (!parse_command_line(args, options, vm, [&] { std::cout << options << '\n'; }))
        return exit_ok;

    const Components components = compose_components(
        vm.count("plugin") != 0 ? vm["plugin"].as<std::vector<std::string>>() : std::vector<std::string>{});
    const auto problem = components.problems.create(vm["problem"].as<std::string>());
    const std::string file = vm["points"].as<std::string>();
    std::vector<PointLine> points;
    if (file == "-") {
        points = read_points(std::cin, "standard input", problem->dimension());
    } else {
        std::ifstream in(file);
        if (!in)
            throw std::runtime_error(file + ": cannot be opened");
        points = read_points(in, file, problem->dimension());
    }
    // Every line is checked before anything is printed, so an error never leaves partial output.
    std::ostringstream out;
    for (const auto& p : points)
        out << format_real(problem->evaluate(p.x)) << '\n';
    std::cout << out.str();
    return exit_ok;
}

} // namespace mhb::cli
