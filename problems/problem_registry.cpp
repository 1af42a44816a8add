#include "problems/problem_registry.hpp"

namespace mhb {

// One line per problem family; each is defined in its own file.
void register_sphere(ProblemRegistry& registry);
void register_bbob(ProblemRegistry& registry);

void register_builtin_problems(ProblemRegistry& registry) {
    register_sphere(registry);
    register_bbob(registry);
}

const ProblemRegistry& builtin_problems() {
    static const ProblemRegistry registry = [] {
        ProblemRegistry r("problem");
        register_builtin_problems(r);
        return r;
    }();
    return registry;
}

} // namespace mhb
