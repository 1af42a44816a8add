// Bad names and parameters of the test-function families are clear errors that name the
// component, the parameter, the value and what is allowed.
#include <gtest/gtest.h>

#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::string spec_error_of(const std::string& spec) {
    try {
        (void)builtin_problems().create(spec);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no error)";
}

void expect_error(const std::string& spec, const std::string& fragment) {
    const std::string message = spec_error_of(spec);
    EXPECT_NE(message.find(fragment), std::string::npos) << spec << " gave: " << message;
}

TEST(FunctionErrors, BadBbobParametersNameTheParameterAndItsRange) {
    expect_error("bbob:f=25", "bbob: parameter 'f' = 25 is outside [1, 24]");
    expect_error("bbob:f=0", "bbob: parameter 'f' = 0 is outside [1, 24]");
    expect_error("bbob:dim=0", "bbob: parameter 'dim' = 0 is outside [2, 40]");
    expect_error("bbob:dim=41", "bbob: parameter 'dim' = 41 is outside [2, 40]");
    expect_error("bbob:instance=-1", "bbob: parameter 'instance' = -1 is outside [1, 100000]");
    expect_error("bbob:instance=0", "bbob: parameter 'instance' = 0 is outside [1, 100000]");
    expect_error("bbob:f=1.5", "bbob: parameter 'f' = 1.5 is not an integer");
    expect_error("bbob:g=3", "bbob: unknown parameter 'g'; known: f, dim, instance");
    // Every error at once, one a line.
    expect_error("bbob:f=25,dim=0", "'f' = 25 is outside [1, 24]\nbbob: parameter 'dim' = 0");
}

TEST(FunctionErrors, BadClassicParametersNameTheParameterAndItsRange) {
    expect_error("rastrigin:dim=0", "rastrigin: parameter 'dim' = 0 is outside [1, 10000]");
    expect_error("rosenbrock:dim=1", "rosenbrock: parameter 'dim' = 1 is outside [2, 10000]");
    expect_error("rastrigin:instance=-1", "rastrigin: parameter 'instance' = -1 is outside [1, 100000]");
    expect_error("rastrigin:shift=maybe", "rastrigin: parameter 'shift' = maybe is not one of on/off");
    expect_error("sphere:bound=0", "sphere: parameter 'bound' = 0 is outside (0, 1e+12]");
    expect_error("rastrigin:noise=1", "rastrigin: unknown parameter 'noise'");
    expect_error("quartic:noise=-1", "quartic: parameter 'noise' = -1 is outside [0, 1e+12]");
    expect_error("sphere:dim=3000,rotate=1", "sphere: parameter 'rotate' needs dim <= 2000");
}

TEST(FunctionErrors, AMisspeltFamilyGetsTheNearNameAndAStrangerTheKnownOnes) {
    EXPECT_EQ(spec_error_of("rastrigen:dim=3"), "unknown problem 'rastrigen'; did you mean 'rastrigin'?");
    const std::string message = spec_error_of("foxholes:dim=3");
    EXPECT_NE(message.find("unknown problem 'foxholes'; known: "), std::string::npos) << message;
    for (const char* name : {"sphere", "rastrigin", "schwefel_2_26", "penalized_2", "bbob"})
        EXPECT_NE(message.find(name), std::string::npos) << name;
}

} // namespace
} // namespace mhb
