// exidel proofs: checks every error-bound constant of predicates/ against the value the
// proofs establish (proofs/README.md). The proven values come from the file that
// proofs/derive_bounds.py writes from Gappa's output; the code's values come from
// constants.hpp itself (included, so the compiler reads the real ones) and, for the range
// limits and the underflow term's skip rule that live in adaptive.cpp and adaptive3d.cpp,
// from those source files.
//
// Usage: check_constants BOUNDS_FILE ADAPTIVE_CPP ADAPTIVE3D_CPP CONSTANTS_HPP
// Exit code 0 iff every claim holds, every constant has a claim, and every
// `inline constexpr double` of constants.hpp (but epsilon) is in the list below.
// A claim marked `if=CONDITION` is proven only if that unproven statement (proofs/bounds.md)
// holds: it is checked like the others, and reported as conditional.
#include <boost/multiprecision/cpp_int.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/predicates/constants.hpp"

namespace {

using Rational = boost::multiprecision::cpp_rational;

// Every constant of constants.hpp that is an error bound or a hypothesis of one. A new
// constant must be added here and get a claim, or the check fails (no silent drift).
std::map<std::string, Rational> code_constants() {
    namespace b = exidel::bounds;
    // cpp_rational(double) is exact: a double is a dyadic rational.
    return {
        {"ccw_a", Rational(b::ccw_a)},
        {"ccw_b", Rational(b::ccw_b)},
        {"ccw_c", Rational(b::ccw_c)},
        {"result_err", Rational(b::result_err)},
        {"icc_a", Rational(b::icc_a)},
        {"icc_b", Rational(b::icc_b)},
        {"icc_c", Rational(b::icc_c)},
        {"icc_dw", Rational(b::icc_dw)},
        {"icc_dw_min", Rational(b::icc_dw_min)},
        {"icc_dw_max", Rational(b::icc_dw_max)},
        {"icc_static", Rational(b::icc_static)},
        {"icc_static_min", Rational(b::icc_static_min)},
        {"icc_static_max", Rational(b::icc_static_max)},
        {"underflow_orient", Rational(b::underflow_orient)},
        {"underflow_incircle", Rational(b::underflow_incircle)},
        {"o3d_a", Rational(b::o3d_a)},
        {"underflow_orient3d", Rational(b::underflow_orient3d)},
        {"o3d_dw", Rational(b::o3d_dw)},
        {"o3d_dw_min", Rational(b::o3d_dw_min)},
        {"o3d_dw_max", Rational(b::o3d_dw_max)},
        {"isp_a", Rational(b::isp_a)},
        {"underflow_insphere", Rational(b::underflow_insphere)},
        {"isp_static", Rational(b::isp_static)},
        {"isp_static_min", Rational(b::isp_static_min)},
        {"isp_static_max", Rational(b::isp_static_max)},
        {"isp_dw", Rational(b::isp_dw)},
        {"isp_dw_min", Rational(b::isp_dw_min)},
        {"isp_dw_max", Rational(b::isp_dw_max)},
        {"cos_rel", Rational(b::cos_rel)},
        {"cos_rel_dot", Rational(b::cos_rel_dot)},
        {"cos_max_dot_rel", Rational(b::cos_max_dot_rel)},
        {"cos_min_factor", Rational(b::cos_min_factor)},
        {"cos_dw", Rational(b::cos_dw)},
        {"cos_dw_min", Rational(b::cos_dw_min)},
        {"cos_dw_max", Rational(b::cos_dw_max)},
        {"dist_a", Rational(b::dist_a)},
        {"underflow_dist", Rational(b::underflow_dist)},
        {"radial_key_rel", Rational(b::radial_key_rel)},
        {"radial_key_min", Rational(b::radial_key_min)},
        {"radial_key_max", Rational(b::radial_key_max)},
        {"circumcenter_rel", Rational(b::circumcenter_rel)},
        {"circumcenter_float_rel", Rational(b::circumcenter_float_rel)},
        // A factor 1 + f: the proof claims its excess f (bounds.md#circumcenter, F2).
        {"circumcenter_float_factor", Rational(b::circumcenter_float_factor) - 1},
        {"circumcenter_margin", Rational(b::circumcenter_margin)},
        {"circumcenter_min_scale", Rational(b::circumcenter_min_scale)},
        {"circumcenter_max_scale", Rational(b::circumcenter_max_scale)},
        {"circumcenter_min_part", Rational(b::circumcenter_min_part)},
        {"circumcenter_min_offset", Rational(b::circumcenter_min_offset)},
        {"circumcenter_max_offset", Rational(b::circumcenter_max_offset)},
    };
}

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Sets values[name] = value; a name that one source already defined is an error (two
// sources must not silently disagree).
void add_unique(std::map<std::string, Rational>& values, const std::string& name,
                const Rational& value, const std::string& path) {
    if (!values.emplace(name, value).second) {
        throw std::runtime_error(name + " defined twice (again in " + path + ")");
    }
}

// The range limits of adaptive.cpp and adaptive3d.cpp: `constexpr int orient_max_log =
// 500;` and the degree passed beside each in `expansion_safe({...}, 2, orient_max_log)`.
void add_range_limits(const std::string& source, const std::string& path,
                      std::map<std::string, Rational>& values) {
    const std::regex limit(R"(constexpr\s+int\s+(\w+_max_log)\s*=\s*(\d+)\s*;)");
    for (std::sregex_iterator it(source.begin(), source.end(), limit), end; it != end; ++it) {
        add_unique(values, (*it)[1], Rational((*it)[2].str()), path);
    }
    const std::regex call(R"(expansion_safe\(\s*\{[^}]*\},\s*(\d+),\s*(\w+)_max_log\))");
    for (std::sregex_iterator it(source.begin(), source.end(), call), end; it != end; ++it) {
        // One predicate may call it more than once (orient_max_log: orient2d and the dot
        // products); every call is checked, so keep the smallest degree.
        const std::string name = (*it)[2].str() + "_degree";
        const Rational degree((*it)[1].str());
        const auto [found, added] = values.emplace(name, degree);
        if (!added && degree < found->second) found->second = degree;
    }
}

// The skip rule of the stage-A underflow term (adaptive3d.cpp's filter_bound, incircle's
// stage A in adaptive.cpp): `first >= 0x1p-960 && spread < 0x1p46`. Every occurrence is
// checked: the smallest threshold of `first` and the largest of `spread` are kept.
int add_skip_rules(const std::string& source, std::map<std::string, Rational>& values) {
    const std::string hex = R"((0x[0-9a-fA-F.]+p[-+]?\d+))";
    const std::regex rule(R"(first\s*>=\s*)" + hex + R"(\s*&&\s*spread\s*<\s*)" + hex);
    int found = 0;
    for (std::sregex_iterator it(source.begin(), source.end(), rule), end; it != end; ++it) {
        // std::strtod reads hexadecimal floating literals exactly; cpp_rational(double) too.
        const Rational first(std::strtod((*it)[1].str().c_str(), nullptr));
        const Rational spread(std::strtod((*it)[2].str().c_str(), nullptr));
        const auto [f, f_added] = values.emplace("skip_first_min", first);
        if (!f_added && first < f->second) f->second = first;
        const auto [s, s_added] = values.emplace("skip_spread_max", spread);
        if (!s_added && spread > s->second) s->second = spread;
        ++found;
    }
    return found;
}

// ---- The formulas the proofs analyse ---------------------------------------------------
// A proven constant is only half of a bound: the proof also fixes the expression it is used
// in (the permanent it multiplies, the term it is added to, the estimate it is compared
// with). These are those expressions, whitespace-normalised, each with the section of
// proofs/bounds.md that analyses it. Every use of a constant (`eb::`) in adaptive.cpp and
// adaptive3d.cpp must lie inside one of them, and each must still be in its file, so an
// edit to a bound's formula (a term dropped, a sign flipped) fails here until the proof is
// changed with it. Mutation testing found such edits that no query could reveal: the
// worst cases they would break are far rarer than any test's inputs (docs/mutation.md).
struct Formula {
    const char* file;   // the source file's name
    const char* text;   // the expression, whitespace-normalised
    const char* proof;  // where proofs/ analyses it
};

const Formula formulas[] = {
    // orient2d and the dot products' stages B and C (product_pair_adapt).
    {"adaptive.cpp", "double det = B[0] + B[1] + B[2] + B[3];",
     "proofs/bounds.md#stages-b-and-c: det = est(B), lemma E"},
    {"adaptive.cpp", "double errbound = eb::ccw_b * sum_abs;",
     "proofs/bounds.md#stages-b-and-c, orient2d stage B"},
    {"adaptive.cpp", "errbound = eb::ccw_c * sum_abs + eb::result_err * std::fabs(det);",
     "proofs/bounds.md#stages-b-and-c, orient2d stage C"},
    // incircle.
    {"adaptive.cpp",
     "const double t = (alift.hi * (std::fabs(bdx.hi * cdy.hi) + std::fabs(cdx.hi * bdy.hi)) + "
     "blift.hi * (std::fabs(cdx.hi * ady.hi) + std::fabs(adx.hi * cdy.hi))) + "
     "clift.hi * (std::fabs(adx.hi * bdy.hi) + std::fabs(bdx.hi * ady.hi)); "
     "return filter_decides(det.hi, eb::icc_dw * t, sign);",
     "proofs/bounds.md#incircle-double-word-stage"},
    {"adaptive.cpp", "if (!in_double_word_range(w, eb::icc_dw_min, eb::icc_dw_max)) return false;",
     "proofs/bounds.md#incircle-double-word-stage, the range"},
    {"adaptive.cpp", "double det = detail::expansion_estimate(fin_length, fin);",
     "proofs/bounds.md#incircle-stages-b-and-c: lemma E"},
    {"adaptive.cpp", "double errbound = eb::icc_b * permanent;",
     "proofs/bounds.md#incircle-stages-b-and-c, stage B"},
    {"adaptive.cpp", "errbound = eb::icc_c * permanent + eb::result_err * std::fabs(det);",
     "proofs/bounds.md#incircle-stages-b-and-c, stage C"},
    {"adaptive.cpp",
     "const double sa = std::fabs(bdxcdy) + std::fabs(cdxbdy); "
     "const double sb = std::fabs(cdxady) + std::fabs(adxcdy); "
     "const double sc = std::fabs(adxbdy) + std::fabs(bdxady); "
     "const double permanent = sa * alift + sb * blift + sc * clift;",
     "proofs/bounds.md#incircle, stage A's permanent"},
    {"adaptive.cpp", "const double spread = ((alift + blift) + (clift + sa)) + ((sb + sc) + 1.0);",
     "proofs/bounds.md#underflow, the skip rule's bound on the underflow term's factor"},
    {"adaptive.cpp",
     "det += ((adx * adx + ady * ady) * ((bdx * cdytail + cdy * bdxtail) - (bdy * cdxtail + "
     "cdx * bdytail)) + 2.0 * (adx * adxtail + ady * adytail) * (bdx * cdy - bdy * cdx)) + "
     "((bdx * bdx + bdy * bdy) * ((cdx * adytail + ady * cdxtail) - (cdy * adxtail + "
     "adx * cdytail)) + 2.0 * (bdx * bdxtail + bdy * bdytail) * (cdx * ady - cdy * adx)) + "
     "((cdx * cdx + cdy * cdy) * ((adx * bdytail + bdy * adxtail) - (ady * bdxtail + "
     "bdx * adytail)) + 2.0 * (cdx * cdxtail + cdy * cdytail) * (adx * bdy - ady * bdx));",
     "proofs/bounds.md#incircle-stages-b-and-c, stage C's first-order correction"},
    {"adaptive.cpp", "const double sum_abs = std::fabs(first) + std::fabs(second);",
     "proofs/bounds.md#orient2d, the dot products' permanent"},
    {"adaptive.cpp", "const double first = eb::icc_a * permanent;",
     "proofs/bounds.md#incircle, stage A"},
    {"adaptive.cpp",
     "const double errbound = negligible ? first : first + eb::underflow_incircle * spread;",
     "proofs/bounds.md#underflow"},
    // The dot products' filter and the cosine test.
    {"adaptive.cpp", "const double errbound = eb::ccw_a * sum_abs + eb::underflow_orient;",
     "proofs/bounds.md#orient2d, #underflow"},
    {"adaptive.cpp",
     "const double tu = std::fabs(adx.hi * bdx.hi) + std::fabs(ady.hi * bdy.hi); "
     "const double tv = std::fabs(acx.hi * bcx.hi) + std::fabs(acy.hi * bcy.hi); "
     "const double t = (ac2.hi * bc2.hi) * (tu * tu) + (ad2.hi * bd2.hi) * (tv * tv); "
     "return filter_decides(diff.hi, eb::cos_dw * t, sign);",
     "proofs/bounds.md#cosine-double-word-stage"},
    {"adaptive.cpp", "if (!in_double_word_range(w, eb::cos_dw_min, eb::cos_dw_max)) return false;",
     "proofs/bounds.md#cosine-double-word-stage, the range"},
    {"adaptive.cpp",
     "const double eu = eb::ccw_a * (std::fabs(u1) + std::fabs(u2)) + eb::underflow_orient;",
     "proofs/bounds.md#orient2d, #underflow"},
    {"adaptive.cpp",
     "const double ev = eb::ccw_a * (std::fabs(v1) + std::fabs(v2)) + eb::underflow_orient;",
     "proofs/bounds.md#orient2d, #underflow"},
    {"adaptive.cpp", "if (du <= eb::cos_max_dot_rel && dv <= eb::cos_max_dot_rel) {",
     "proofs/cosine.md, the filter"},
    {"adaptive.cpp", "if (smallest >= eb::cos_min_factor && left <= largest && right <= largest) {",
     "proofs/cosine.md, the filter"},
    {"adaptive.cpp",
     "const double errbound = (eb::cos_rel + eb::cos_rel_dot * du) * left + (eb::cos_rel + "
     "eb::cos_rel_dot * dv) * right;",
     "proofs/cosine.md, the filter"},
    // compare_distance.
    {"adaptive.cpp", "const double errbound = eb::dist_a * permanent + eb::underflow_dist;",
     "proofs/bounds.md#compare-distance"},
    // orient3d and insphere.
    {"adaptive3d.cpp",
     "return filter_decides(det, filter_bound(eb::o3d_a * permanent, eb::underflow_orient3d, "
     "spread),",
     "proofs/bounds.md#orient3d, #underflow"},
    {"adaptive3d.cpp",
     "const double t = (std::fabs(adz.hi) * (std::fabs(bdx.hi * cdy.hi) + "
     "std::fabs(cdx.hi * bdy.hi)) + std::fabs(bdz.hi) * (std::fabs(cdx.hi * ady.hi) + "
     "std::fabs(adx.hi * cdy.hi))) + std::fabs(cdz.hi) * (std::fabs(adx.hi * bdy.hi) + "
     "std::fabs(bdx.hi * ady.hi)); return filter_decides(det.hi, eb::o3d_dw * t, sign);",
     "proofs/bounds.md#orient3d-double-word-stage"},
    {"adaptive3d.cpp",
     "if (!detail::in_double_word_range(w, eb::o3d_dw_min, eb::o3d_dw_max)) return false;",
     "proofs/bounds.md#orient3d-double-word-stage, the range"},
    {"adaptive3d.cpp", "if (mm >= eb::isp_static_min && mm <= eb::isp_static_max) [[likely]] {",
     "proofs/bounds.md#insphere-semi-static-filter, the range"},
    {"adaptive3d.cpp", "return filter_decides(det, eb::isp_static * ((m2 * m2) * mm), sign);",
     "proofs/bounds.md#insphere-semi-static-filter"},
    {"adaptive3d.cpp",
     "return filter_decides(det, filter_bound(eb::isp_a * permanent, eb::underflow_insphere, "
     "spread),",
     "proofs/bounds.md#insphere, #underflow"},
    {"adaptive3d.cpp",
     "const auto pair = [](Word p, Word q, Word r, Word s) { return std::fabs(p.hi * q.hi) + "
     "std::fabs(r.hi * s.hi); }; const double abp = pair(aex, bey, bex, aey), "
     "bcp = pair(bex, cey, cex, bey); const double cdp = pair(cex, dey, dex, cey), "
     "dap = pair(dex, aey, aex, dey); const double acp = pair(aex, cey, cex, aey), "
     "bdp = pair(bex, dey, dex, bey); const double aezp = std::fabs(aez.hi), "
     "bezp = std::fabs(bez.hi), cezp = std::fabs(cez.hi), dezp = std::fabs(dez.hi); "
     "const double t = ((cdp * bezp + bdp * cezp) + bcp * dezp) * alift.hi + "
     "((dap * cezp + acp * dezp) + cdp * aezp) * blift.hi + "
     "((abp * dezp + bdp * aezp) + dap * bezp) * clift.hi + "
     "((bcp * aezp + acp * bezp) + abp * cezp) * dlift.hi; "
     "return filter_decides(det.hi, eb::isp_dw * t, sign);",
     "proofs/bounds.md#insphere-double-word-stage"},
    {"adaptive3d.cpp",
     "if (!detail::in_double_word_range(w, eb::isp_dw_min, eb::isp_dw_max)) return false;",
     "proofs/bounds.md#insphere-double-word-stage, the range"},
};

// The source with comments removed and every run of whitespace made one space.
std::string normalised(const std::string& source) {
    std::string out;
    bool space = false;
    for (std::size_t i = 0; i < source.size(); ++i) {
        if (source.compare(i, 2, "//") == 0) {
            while (i < source.size() && source[i] != '\n') ++i;
            space = true;
            continue;
        }
        const char c = source[i];
        if (c == ' ' || c == '\n' || c == '\t' || c == '\r') {
            space = true;
            continue;
        }
        // No space after an opening or before a closing bracket: a line break there is
        // the formatter's.
        if (space && !out.empty() && out.back() != '(' && out.back() != '[' && c != ')' &&
            c != ']') {
            out += ' ';
        }
        space = false;
        out += c;
    }
    return out;
}

// Fails for every pinned formula missing from `path` and every use of a constant outside one.
int check_formulas(const std::string& source, const std::string& path) {
    const std::string name = path.substr(path.find_last_of('/') + 1);
    const std::string text = normalised(source);
    std::vector<bool> covered(text.size(), false);
    int failures = 0;
    for (const Formula& f : formulas) {
        if (name != f.file) continue;
        const std::string pinned = normalised(f.text);
        std::size_t at = text.find(pinned), count = 0;
        for (; at != std::string::npos; at = text.find(pinned, at + 1), ++count) {
            for (std::size_t i = at; i < at + pinned.size(); ++i) covered[i] = true;
        }
        if (count == 0) {
            std::cout << "FAIL " << name << ": the formula `" << f.text << "` (" << f.proof
                      << ") is not in the code: change the proof with the code\n";
            ++failures;
        }
    }
    std::size_t reported_to = 0;  // one line per statement
    for (std::size_t at = text.find("eb::"); at != std::string::npos;
         at = text.find("eb::", at + 1)) {
        if (covered[at] || at < reported_to) continue;
        const std::size_t semicolon = text.rfind(';', at);
        const std::size_t from = semicolon == std::string::npos ? 0 : semicolon + 2;
        reported_to = text.find(';', at) + 1;
        std::cout << "FAIL " << name << ": a bound used outside the proven formulas: `"
                  << text.substr(from, reported_to - from) << "`\n";
        ++failures;
    }
    return failures;
}

// The list in code_constants() is written by hand; this makes sure it is complete.
int unlisted_constants(const std::string& header, const std::map<std::string, Rational>& values) {
    const std::regex declaration(R"(inline\s+constexpr\s+double\s+(\w+)\s*=)");
    int missing = 0;
    for (std::sregex_iterator it(header.begin(), header.end(), declaration), end; it != end; ++it) {
        const std::string name = (*it)[1];
        if (name != "epsilon" && !values.contains(name)) {
            std::cout << "FAIL " << name << ": in constants.hpp but not checked by "
                      << "check_constants.cpp (add it to code_constants() and give it a proof)\n";
            ++missing;
        }
    }
    return missing;
}

std::string show(const Rational& r) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", r.convert_to<double>());
    return buf;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::cerr << "usage: check_constants BOUNDS_FILE ADAPTIVE_CPP ADAPTIVE3D_CPP "
                     "CONSTANTS_HPP\n";
        return 2;
    }
    try {
        std::map<std::string, Rational> values = code_constants();
        int failures = 0;
        for (const char* path : {argv[2], argv[3]}) {
            const std::string source = read_file(path);
            add_range_limits(source, path, values);
            failures += check_formulas(source, path);
            // Each file has the rule once (incircle's stage A; filter_bound): a rule the
            // regular expression no longer finds would go unchecked.
            if (add_skip_rules(source, values) == 0) {
                std::cout << "FAIL " << path << ": the underflow term's skip rule (first >= "
                          << "... && spread < ...) not found\n";
                ++failures;
            }
        }

        std::istringstream bounds(read_file(argv[1]));
        std::set<std::string> claimed;
        std::map<std::string, std::set<std::string>> conditional;  // constant -> conditions
        failures += unlisted_constants(read_file(argv[4]), values);
        std::string line;
        while (std::getline(bounds, line)) {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream fields(line);
            std::string name, kind, value, condition, extra;
            if (!(fields >> name >> kind >> value) || (kind != "min" && kind != "max")) {
                throw std::runtime_error("malformed line in bounds file: " + line);
            }
            if (fields >> condition) {
                const bool bad = condition.rfind("if=", 0) != 0 || condition.size() == 3;
                if (bad || (fields >> extra)) {
                    throw std::runtime_error("malformed line in bounds file: " + line);
                }
                condition = condition.substr(3);
            }
            const Rational proven(value);
            const auto found = values.find(name);
            if (found == values.end()) {
                std::cout << "FAIL " << name << ": proven, but not found in the code\n";
                ++failures;
                continue;
            }
            claimed.insert(name);
            const Rational& code = found->second;
            const bool ok = kind == "min" ? code >= proven : code <= proven;
            if (!condition.empty()) conditional[name].insert(condition);
            std::cout << (ok ? "ok   " : "FAIL ") << name << " = " << show(code)
                      << (kind == "min" ? " >= " : " <= ") << show(proven)
                      << (condition.empty() ? " (proven" : " (proven if " + condition + " holds")
                      << (ok ? ""
                             : "; the code's value is outside the proven range, by " +
                                   show(abs(proven - code) / proven) + " relative")
                      << ")\n";
            failures += ok ? 0 : 1;
        }
        for (const auto& [name, code] : values) {
            if (!claimed.contains(name)) {
                std::cout << "FAIL " << name << " = " << show(code) << ": no proof claims it\n";
                ++failures;
            }
        }
        if (failures != 0) {
            std::cout << "constants NOT proven\n";
        } else if (conditional.empty()) {
            std::cout << "all constants proven\n";
        } else {
            std::cout << "all claims hold; proven only under an unproven condition "
                         "(proofs/bounds.md):";
            const char* separator = " ";
            for (const auto& [name, conditions] : conditional) {
                for (const auto& c : conditions) {
                    std::cout << separator << name << " (" << c << ")";
                    separator = ", ";
                }
            }
            std::cout << "\n";
        }
        return failures == 0 ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "check_constants: " << error.what() << "\n";
        return 2;
    }
}
