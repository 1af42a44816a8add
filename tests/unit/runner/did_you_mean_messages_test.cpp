// What a misspelt name is told, from the registries, the parameter lists and the spec reader.
#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/spec.hpp"
#include "problems/problem_registry.hpp"
#include "runner/cli/parse_command_line.hpp"

namespace mhb {
namespace {

std::string refusal_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "no refusal";
}

TEST(DidYouMean, EveryRegistryAndParameterListSuggests) {
    EXPECT_EQ(refusal_of([] { (void)builtin_algorithms().find("itlob"); }),
              "unknown algorithm 'itlob'; did you mean 'itlbo'?");
    EXPECT_EQ(refusal_of([] { (void)builtin_problems().find("rastrign"); }),
              "unknown problem 'rastrign'; did you mean 'rastrigin'?");
    EXPECT_EQ(refusal_of([] { (void)builtin_algorithms().validate(Spec::parse("itlbo:popsize=3")); }),
              "itlbo: unknown parameter 'popsize'; known: np, tutorial, stepwise, obl, p, obl_greedy, "
              "obl_bounds, r");
    EXPECT_EQ(refusal_of([] { (void)builtin_algorithms().validate(Spec::parse("itlbo:nq=30")); }),
              "itlbo: unknown parameter 'nq'; did you mean 'np'?");
}

TEST(SpecLists, ACommaSeparatedListIsToldToUseSpaces) {
    EXPECT_EQ(refusal_of([] { (void)Spec::parse("itlbo,pso"); }),
              "'itlbo,pso': separate several with spaces, not commas: itlbo pso");
    EXPECT_EQ(
        refusal_of([] { (void)Spec::parse("itlbo:np=10,pso"); }),
        "'itlbo:np=10,pso': pso is not key=value; to name several components, separate them with spaces");
    EXPECT_EQ(refusal_of([] { (void)Spec::parse("pso:w"); }), "'pso:w': w is not key=value");
}

TEST(DidYouMean, AMisspeltOptionIsToldTheNearOne) {
    namespace po = boost::program_options;
    po::options_description options("Options");
    options.add_options()("help,h", "this text")("threads", po::value<int>(),
                                                 "threads")("no-figures", po::bool_switch(), "no figures");
    const auto refusal = [&](const std::vector<std::string>& args) {
        po::variables_map vm;
        try {
            (void)cli::parse_command_line(args, options, vm, [] {});
        } catch (const po::error& e) {
            return std::string(e.what());
        }
        return std::string("no refusal");
    };
    EXPECT_EQ(refusal({"--therads", "2"}), "unrecognised option '--therads'; did you mean '--threads'?");
    EXPECT_EQ(refusal({"--no-figure"}), "no refusal"); // Boost takes an unambiguous beginning as it is
    EXPECT_EQ(refusal({"--nofigures"}), "unrecognised option '--nofigures'; did you mean '--no-figures'?");
    EXPECT_EQ(refusal({"--colour"}), "unrecognised option '--colour'");
}

} // namespace
} // namespace mhb
