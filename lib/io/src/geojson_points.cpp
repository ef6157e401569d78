// exidel I/O: reading points from GeoJSON (RFC 7946; the format: exidel/io/points.hpp).
//
// The text is parsed into a small tree whose every value knows its line, then walked:
// GeoJSON's members come in any order (a "type" may follow its "coordinates"), so a
// feature cannot be decided while streaming through it. Numbers keep their text and are
// converted when used, so that a property nobody asks for may hold any JSON number.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exidel/io/constraints.hpp"
#include "exidel/io/number.hpp"
#include "exidel/io/points.hpp"
#include "geojson_points.hpp"

namespace exidel::io::detail {

namespace {

struct Value {
    enum class Kind { null, boolean, number, string, array, object };
    Kind kind = Kind::null;
    std::size_t line = 1;
    bool boolean = false;
    std::string_view number;  // the number's text
    std::string string;
    std::vector<Value> items;       // an array's; an object's member values
    std::vector<std::string> keys;  // an object's member names, one per item

    const Value* member(std::string_view key) const {
        for (std::size_t k = 0; k < keys.size(); ++k) {
            if (keys[k] == key) return &items[k];
        }
        return nullptr;
    }
};

std::string_view kind_name(Value::Kind k) {
    switch (k) {
        case Value::Kind::null: return "null";
        case Value::Kind::boolean: return "a boolean";
        case Value::Kind::number: return "a number";
        case Value::Kind::string: return "a string";
        case Value::Kind::array: return "an array";
        case Value::Kind::object: return "an object";
    }
    return "?";
}

// RFC 8259 JSON, strictly; nesting is limited so that hostile input cannot exhaust the
// stack.
class Parser {
public:
    explicit Parser(std::string_view s) : s_(s) {}

    Value document() {
        Value v = value(0);
        space();
        if (i_ < s_.size()) fail("unexpected " + found() + " after the JSON value");
        return v;
    }

private:
    static constexpr int max_depth = 200;

    [[noreturn]] void fail(const std::string& why) const { throw ReadError::at_line(line_, why); }

    std::string found() const {
        if (i_ >= s_.size()) return "the end of the input";
        std::size_t k = i_ + 1;
        while (k < s_.size() && k < i_ + 12 && s_[k] != '\n' && s_[k] != ' ') ++k;
        return quoted(s_.substr(i_, k - i_));
    }

    void space() {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == '\n') {
                ++line_;
            } else if (c != ' ' && c != '\t' && c != '\r') {
                break;
            }
            ++i_;
        }
    }

    bool literal(std::string_view word) {
        if (s_.substr(i_, word.size()) != word) return false;
        i_ += word.size();
        return true;
    }

    Value value(int depth) {
        if (depth > max_depth) fail("nested more than " + std::to_string(max_depth) + " deep");
        space();
        Value v;
        v.line = line_;
        if (i_ >= s_.size()) fail("expected a JSON value, found the end of the input");
        const char c = s_[i_];
        if (c == '{') {
            v.kind = Value::Kind::object;
            ++i_;
            space();
            if (i_ < s_.size() && s_[i_] == '}') {
                ++i_;
                return v;
            }
            for (;;) {
                space();
                if (i_ >= s_.size() || s_[i_] != '"')
                    fail("expected a key string, found " + found());
                std::string key = string();
                space();
                if (i_ >= s_.size() || s_[i_] != ':')
                    fail("expected ':' after a key, found " + found());
                ++i_;
                v.keys.push_back(std::move(key));
                v.items.push_back(value(depth + 1));
                space();
                if (i_ < s_.size() && s_[i_] == ',') {
                    ++i_;
                    continue;
                }
                if (i_ < s_.size() && s_[i_] == '}') {
                    ++i_;
                    return v;
                }
                fail("expected ',' or '}' in an object, found " + found());
            }
        }
        if (c == '[') {
            v.kind = Value::Kind::array;
            ++i_;
            space();
            if (i_ < s_.size() && s_[i_] == ']') {
                ++i_;
                return v;
            }
            for (;;) {
                v.items.push_back(value(depth + 1));
                space();
                if (i_ < s_.size() && s_[i_] == ',') {
                    ++i_;
                    continue;
                }
                if (i_ < s_.size() && s_[i_] == ']') {
                    ++i_;
                    return v;
                }
                fail("expected ',' or ']' in an array, found " + found());
            }
        }
        if (c == '"') {
            v.kind = Value::Kind::string;
            v.string = string();
            return v;
        }
        if (literal("true") || literal("false")) {
            v.kind = Value::Kind::boolean;
            v.boolean = s_[i_ - 1] == 'e' && s_[i_ - 2] == 'u';
            return v;
        }
        if (literal("null")) return v;
        if (c == '-' || (c >= '0' && c <= '9')) {
            v.kind = Value::Kind::number;
            v.number = number();
            return v;
        }
        if (literal("NaN") || literal("Infinity")) {
            fail("NaN and Infinity are not JSON numbers");
        }
        fail("expected a JSON value, found " + found());
    }

    // RFC 8259's number grammar; the text.
    std::string_view number() {
        const std::size_t start = i_;
        const auto digits = [&] {
            const std::size_t d = i_;
            while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
            return i_ - d;
        };
        if (s_[i_] == '-') ++i_;
        if (i_ < s_.size() && s_[i_] == '0') {
            ++i_;
        } else if (digits() == 0) {
            fail("a '-' without digits is not a JSON number");
        }
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            if (digits() == 0) fail("digits must follow '.' in a JSON number");
        }
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            ++i_;
            if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
            if (digits() == 0) fail("digits must follow the exponent of a JSON number");
        }
        if (i_ < s_.size() &&
            ((s_[i_] >= '0' && s_[i_] <= '9') || s_[i_] == '.' ||
             (s_[i_] >= 'a' && s_[i_] <= 'z') || (s_[i_] >= 'A' && s_[i_] <= 'Z'))) {
            fail(quoted(s_.substr(start, i_ + 1 - start)) + " is not a JSON number");
        }
        return s_.substr(start, i_ - start);
    }

    static void utf8(std::string& out, std::uint32_t c) {
        if (c < 0x80) {
            out += static_cast<char>(c);
        } else if (c < 0x800) {
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
        } else if (c < 0x10000) {
            out += static_cast<char>(0xE0 | (c >> 12));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (c & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (c >> 18));
            out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (c & 0x3F));
        }
    }

    std::uint32_t hex4() {
        if (i_ + 4 > s_.size()) fail("a \\u escape needs four hexadecimal digits");
        std::uint32_t v = 0;
        for (int k = 0; k < 4; ++k) {
            const char h = s_[i_++];
            v <<= 4;
            if (h >= '0' && h <= '9') {
                v |= static_cast<std::uint32_t>(h - '0');
            } else if (h >= 'a' && h <= 'f') {
                v |= static_cast<std::uint32_t>(h - 'a' + 10);
            } else if (h >= 'A' && h <= 'F') {
                v |= static_cast<std::uint32_t>(h - 'A' + 10);
            } else {
                fail("a \\u escape needs four hexadecimal digits");
            }
        }
        return v;
    }

    // A string at s_[i_] == '"', its escapes decoded.
    std::string string() {
        std::string out;
        ++i_;
        for (;;) {
            if (i_ >= s_.size()) fail("unterminated string");
            const char c = s_[i_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("a control character inside a string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (i_ >= s_.size()) fail("unterminated string");
            const char e = s_[i_++];
            switch (e) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    std::uint32_t u = hex4();
                    if (u >= 0xD800 && u < 0xDC00 && s_.substr(i_, 2) == "\\u") {
                        i_ += 2;
                        const std::uint32_t low = hex4();
                        if (low < 0xDC00 || low >= 0xE000) fail("an unpaired UTF-16 surrogate");
                        u = 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00);
                    }
                    utf8(out, u);
                    break;
                }
                default: fail("unknown escape \\" + std::string(1, e) + " in a string");
            }
        }
    }

    std::string_view s_;
    std::size_t i_ = 0;
    std::size_t line_ = 1;
};

// Walks the tree into points (and z).
class Reader {
public:
    /// With `segments`, lines and polygons are read too (constraints mode): their
    /// consecutive positions become points joined by segments.
    Reader(const std::optional<std::string>& z_property, PointFile& out,
           std::vector<std::array<std::uint32_t, 2>>* segments = nullptr)
        : z_property_(z_property), out_(out), segments_(segments) {}

    void document(const Value& v) {
        const std::string type = type_of(v, "the GeoJSON text");
        if (type == "FeatureCollection") {
            const Value* features = v.member("features");
            if (!features || features->kind != Value::Kind::array) {
                throw ReadError::at_line(v.line, "a FeatureCollection needs a \"features\" array");
            }
            for (std::size_t k = 0; k < features->items.size(); ++k) {
                feature(features->items[k], "feature " + std::to_string(k));
            }
        } else if (type == "Feature") {
            feature(v, "the feature");
        } else {
            if (z_property_) {
                throw ReadError::at_line(v.line, "--z-property " + quoted(*z_property_) +
                                                     ": a bare geometry has no properties");
            }
            geometry(v, "the geometry", std::nullopt);
        }
        if (!has_z_.value_or(false)) out_.z.clear();
    }

private:
    std::string type_of(const Value& v, const std::string& what) const {
        if (v.kind != Value::Kind::object) {
            throw ReadError::at_line(
                v.line, what + " is " + std::string(kind_name(v.kind)) + ", not a GeoJSON object");
        }
        const Value* t = v.member("type");
        if (!t || t->kind != Value::Kind::string) {
            throw ReadError::at_line(v.line, what + " has no \"type\" string");
        }
        return t->string;
    }

    void feature(const Value& f, const std::string& name) {
        if (type_of(f, name) != "Feature") {
            throw ReadError::at_line(
                f.line, name + ": type " + quoted(type_of(f, name)) + ", expected \"Feature\"");
        }
        const Value* g = f.member("geometry");
        if (!g) throw ReadError::at_line(f.line, name + " has no \"geometry\" member");
        if (g->kind == Value::Kind::null) return;  // an unlocated feature: no point
        std::optional<double> z;
        if (z_property_) z = property_z(f, name);
        geometry(*g, name, z);
    }

    double property_z(const Value& f, const std::string& name) const {
        const Value* props = f.member("properties");
        const Value* p =
            props && props->kind == Value::Kind::object ? props->member(*z_property_) : nullptr;
        if (!p) {
            throw ReadError::at_line(
                f.line, name + ": no property " + quoted(*z_property_) + " (--z-property)");
        }
        if (p->kind != Value::Kind::number) {
            throw ReadError::at_line(p->line, name + ": property " + quoted(*z_property_) + " is " +
                                                  std::string(kind_name(p->kind)) +
                                                  ", not a number (--z-property)");
        }
        return number(*p, name + ": property " + quoted(*z_property_));
    }

    static double number(const Value& v, const std::string& what) {
        const ParsedNumber n = parse_double(v.number);
        if (!n.value) throw ReadError::at_line(v.line, what + ": " + n.error);
        return *n.value;
    }

    void geometry(const Value& g, const std::string& name, std::optional<double> z) {
        const std::string type = type_of(g, name + "'s geometry");
        if (type == "GeometryCollection") {
            const Value* members = g.member("geometries");
            if (!members || members->kind != Value::Kind::array) {
                throw ReadError::at_line(g.line, name +
                                                     ": a GeometryCollection needs a "
                                                     "\"geometries\" array");
            }
            for (std::size_t k = 0; k < members->items.size(); ++k) {
                geometry(members->items[k], name + ", geometry " + std::to_string(k), z);
            }
            return;
        }
        if (segments_ && (type == "LineString" || type == "MultiLineString" || type == "Polygon" ||
                          type == "MultiPolygon")) {
            lines(g, type, name, z);
            return;
        }
        if (type != "Point" && type != "MultiPoint") {
            if (segments_) {
                throw ReadError::at_line(g.line, name + ": geometry type " + quoted(type) +
                                                     " is not supported (Point, MultiPoint, "
                                                     "LineString, MultiLineString, Polygon, "
                                                     "MultiPolygon or GeometryCollection)");
            }
            throw ReadError::at_line(g.line, name + ": geometry type " + quoted(type) +
                                                 " is not supported (Point, MultiPoint or "
                                                 "GeometryCollection of them)");
        }
        const Value* c = g.member("coordinates");
        if (!c) throw ReadError::at_line(g.line, name + ": a " + type + " needs \"coordinates\"");
        if (type == "Point") {
            position(*c, name, z);
            return;
        }
        if (c->kind != Value::Kind::array) {
            throw ReadError::at_line(c->line, name +
                                                  ": a MultiPoint's coordinates are an array "
                                                  "of positions");
        }
        for (const Value& p : c->items) position(p, name, z);
    }

    static const Value& array_of(const Value* v, const Value& owner, const std::string& what) {
        if (!v) throw ReadError::at_line(owner.line, what + " needs \"coordinates\"");
        if (v->kind != Value::Kind::array) {
            throw ReadError::at_line(
                v->line, what + " is " + std::string(kind_name(v->kind)) + ", not an array");
        }
        return *v;
    }

    // A LineString's positions joined in order; a ring's too, and closed.
    void path(const Value& positions, const std::string& name, std::optional<double> z, bool ring) {
        const std::size_t n = positions.items.size();
        if (!ring && n < 2) {
            throw ReadError::at_line(
                positions.line,
                name + ": a LineString needs at least 2 positions, got " + std::to_string(n));
        }
        if (ring && n < 4) {
            throw ReadError::at_line(
                positions.line,
                name + ": a linear ring needs at least 4 positions, got " + std::to_string(n));
        }
        const auto first = static_cast<std::uint32_t>(out_.points.size());
        for (std::size_t k = 0; k < n; ++k) {
            position(positions.items[k], name, z);
            if (k > 0)
                segments_->push_back({first + static_cast<std::uint32_t>(k) - 1,
                                      first + static_cast<std::uint32_t>(k)});
        }
        if (ring) {
            // RFC 7946: the last position is the first again. It is dropped, and the last
            // segment goes back to the first point.
            const Point2 a = out_.points[first], b = out_.points.back();
            if (a.x != b.x || a.y != b.y) {
                throw ReadError::at_line(positions.items.back().line,
                                         name + ": a linear ring must end where it starts");
            }
            out_.points.pop_back();
            if (!out_.z.empty()) out_.z.pop_back();
            segments_->back()[1] = first;
        }
    }

    void lines(const Value& g, const std::string& type, const std::string& name,
               std::optional<double> z) {
        const Value& c = array_of(g.member("coordinates"), g, name + ": a " + type);
        const auto polygon = [&](const Value& rings, const std::string& what) {
            if (rings.kind != Value::Kind::array) {
                throw ReadError::at_line(rings.line, what + ": a Polygon is an array of rings");
            }
            for (std::size_t r = 0; r < rings.items.size(); ++r) {
                const Value& ring = rings.items[r];
                if (ring.kind != Value::Kind::array) {
                    throw ReadError::at_line(ring.line,
                                             what + ": a linear ring is an array of positions");
                }
                path(ring, what + ", ring " + std::to_string(r), z, true);
            }
        };
        if (type == "LineString") {
            path(c, name, z, false);
        } else if (type == "Polygon") {
            polygon(c, name);
        } else {
            for (std::size_t k = 0; k < c.items.size(); ++k) {
                const Value& part = c.items[k];
                const std::string what = name + ", part " + std::to_string(k);
                if (type == "MultiPolygon") {
                    polygon(part, what);
                } else if (part.kind != Value::Kind::array) {
                    throw ReadError::at_line(part.line,
                                             what + ": a LineString is an array of positions");
                } else {
                    path(part, what, z, false);
                }
            }
        }
    }

    void position(const Value& p, const std::string& name, std::optional<double> z) {
        if (p.kind != Value::Kind::array || p.items.size() < 2 || p.items.size() > 3) {
            throw ReadError::at_line(
                p.line,
                name + ": a position is [x, y] or [x, y, z], got " +
                    (p.kind == Value::Kind::array ? std::to_string(p.items.size()) + " coordinates"
                                                  : std::string(kind_name(p.kind))));
        }
        double c[3] = {0, 0, 0};
        static constexpr const char* names[3] = {"x", "y", "z"};
        for (std::size_t k = 0; k < p.items.size(); ++k) {
            if (p.items[k].kind != Value::Kind::number) {
                throw ReadError::at_line(p.items[k].line,
                                         name + ": " + names[k] + " is " +
                                             std::string(kind_name(p.items[k].kind)) +
                                             ", not a number");
            }
            c[k] = number(p.items[k], name + ": " + names[k]);
        }
        const bool with_z = z.has_value() || p.items.size() == 3;
        if (!has_z_) has_z_ = with_z;
        if (*has_z_ != with_z) {
            throw ReadError::at_line(p.line, name + ": a position " +
                                                 (with_z ? "with" : "without") +
                                                 " z, where the earlier ones are " +
                                                 (with_z ? "without" : "with") + " z");
        }
        out_.points.push_back({c[0], c[1]});
        if (with_z) out_.z.push_back(z ? *z : c[2]);
    }

    const std::optional<std::string>& z_property_;
    PointFile& out_;
    std::vector<std::array<std::uint32_t, 2>>* segments_;
    std::optional<bool> has_z_;
};

}  // namespace

PointFile parse_geojson_points(std::string_view data,
                               const std::optional<std::string>& z_property) {
    PointFile file;
    Parser parser(data);
    std::size_t first = 0;
    while (first < data.size() && (data[first] == ' ' || data[first] == '\t' ||
                                   data[first] == '\r' || data[first] == '\n')) {
        ++first;
    }
    if (first == data.size()) return file;  // empty input: 0 points
    const Value document = parser.document();
    Reader(z_property, file).document(document);
    return file;
}

}  // namespace exidel::io::detail

namespace exidel::io {

ConstraintFile parse_geojson_constraints(std::string_view data) {
    ConstraintFile file;
    PointFile points;
    std::size_t first = 0;
    while (first < data.size() && (data[first] == ' ' || data[first] == '\t' ||
                                   data[first] == '\r' || data[first] == '\n')) {
        ++first;
    }
    if (first == data.size()) return file;  // empty input: nothing
    detail::Parser parser(data);
    const detail::Value document = parser.document();
    const std::optional<std::string> no_z_property;
    detail::Reader(no_z_property, points, &file.segments).document(document);
    file.points = std::move(points.points);
    file.z = std::move(points.z);
    return file;
}

}  // namespace exidel::io
