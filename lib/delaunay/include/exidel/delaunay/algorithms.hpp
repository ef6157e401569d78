// exidel: the one list of triangulation algorithms.
//
// EXIDEL_DELAUNAY_ALGORITHMS(X) expands X(name, "spelling", Type, takes_order, "summary")
// once per algorithm, in the order help texts and studies list them:
//   name     the enumerator of Algorithm;
//   spelling its name on every command line, in --stats ("algorithm"), in the research
//            tables and in fixture file names;
//   Type     detail::Type, the algorithm: one header in detail/ with
//              template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
//              static void run(const K&, const detail::SortedInput&, const Options&,
//                              detail::MeshOutput&, Result&);
//            over the shared mesh (detail/mesh.hpp), included by triangulate.hpp;
//   takes_order  whether Options::strategy (--order) chooses how it runs; the studies run
//            such an algorithm once per order;
//   summary  one line: what it does and what it costs.
// Everything that enumerates algorithms (triangulate's dispatch, `exidel triangulate
// --algorithm`, `exidel study triangulation --algorithm`, the benchmark) reads this list,
// so a new algorithm is its header, its #include in triangulate.hpp and one line here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

// clang-format off
#define EXIDEL_DELAUNAY_ALGORITHMS(X)                                                          \
    X(external, "external", ExternalIncremental, true,                                         \
      "Cai 2025, each point outside the hull; O(n log n) expected (radial, strips)")          \
    X(bowyer_watson, "bowyer-watson", BowyerWatson, false,                                     \
      "BRIO order, walk to the point, cavity of conflicting triangles re-fanned; O(n log n) expected") \
    X(randomized, "randomized", RandomizedIncremental, false,                                  \
      "de Berg et al. ch. 9: random order, history DAG, Lawson flips; O(n log n) expected") \
    X(lawson, "lawson", Lawson, false,                                                         \
      "Lawson 1977: the sorted fan, then flips until no edge is illegal; O(n^2) flips worst case") \
    X(sweep_hull, "sweep-hull", SweepHull, false,                                              \
      "Sinclair's s-hull: exact radial order, fan to the visible hull, Lawson flips; O(n log n)") \
    X(divide_and_conquer, "divide-and-conquer", DivideAndConquer, false,                       \
      "Guibas-Stolfi: vertical cuts down to triangles, zipper merges; O(n log n)")          \
    X(dwyer, "dwyer", Dwyer, false,                                                            \
      "Guibas-Stolfi with Dwyer's alternating cuts (Triangle's default); O(n log n), ~n merge work on uniform")
// clang-format on

namespace exidel::delaunay {

/// Which algorithm triangulate() runs (Options::algorithm).
enum class Algorithm : std::uint8_t {
#define EXIDEL_ALGORITHM_ENUMERATOR_(name, spelling, Type, takes_order, summary) name,
    EXIDEL_DELAUNAY_ALGORITHMS(EXIDEL_ALGORITHM_ENUMERATOR_)
#undef EXIDEL_ALGORITHM_ENUMERATOR_
};

struct AlgorithmInfo {
    Algorithm id;
    std::string_view name;
    bool takes_order;  ///< Options::strategy applies
    std::string_view summary;
};

/// Every algorithm, in list order.
std::span<const AlgorithmInfo> algorithms() noexcept;

std::string_view to_string(Algorithm algorithm) noexcept;

/// The algorithm a name spells; nullopt for anything else.
std::optional<Algorithm> algorithm_from_name(std::string_view name) noexcept;

/// "external|...", for usage lines and error messages.
std::string algorithm_spellings();

/// One line per algorithm, "  <name>  <summary>", for --help texts.
std::string algorithm_help();

}  // namespace exidel::delaunay
