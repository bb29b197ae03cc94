// parse_vertex_selector, select_vertices (vertex_selector.hpp).
#include "vertex_selector.hpp"

#include <algorithm>
#include <charconv>
#include <optional>

#include "command_line.hpp"
#include "sxk/traversal.hpp"

namespace sxk::elasticity {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

// One term, or the reason it does not parse.
std::variant<SelectorTerm, std::string> parse_term(std::string_view term) {
    SelectorTerm t;
    if (term == "boundary") {
        t.kind = SelectorTerm::Kind::boundary;
        return t;
    }
    if (term.rfind("label", 0) == 0) {
        const std::string_view rest = trim(term.substr(5));
        if (rest.empty() || rest.front() != '=')
            return std::string("expected '=' after 'label'");
        const std::string_view number = trim(rest.substr(1));
        const char* end = number.data() + number.size();
        const auto [at, error] = std::from_chars(number.data(), end, t.label);
        if (number.empty() || error != std::errc() || at != end)
            return "expected a whole number after 'label=', found '" + std::string(number) + "'";
        t.kind = SelectorTerm::Kind::label;
        return t;
    }
    if (term.empty() || (term.front() != 'x' && term.front() != 'y' && term.front() != 'z'))
        return std::string("expected x, y or z compared with a number, label=N or boundary");
    t.kind = SelectorTerm::Kind::coordinate;
    t.axis = term.front() - 'x';
    std::string_view rest = trim(term.substr(1));
    std::string_view op;
    for (const std::string_view candidate : {"<=", ">=", "<", ">", "="})
        if (rest.rfind(candidate, 0) == 0) {
            op = candidate;
            break;
        }
    if (op.empty())
        return "expected one of < <= > >= = after '" + std::string(1, term.front()) + "'";
    using C = SelectorTerm::Compare;
    t.compare = op == "<"    ? C::less
                : op == "<=" ? C::less_equal
                : op == ">"  ? C::greater
                : op == ">=" ? C::greater_equal
                             : C::equal;
    const std::string_view number = trim(rest.substr(op.size()));
    const std::optional<double> value = parse_finite_number(number);
    if (!value)
        return "expected a number after '" + std::string(op) + "', found '" + std::string(number) +
               "'";
    t.value = *value;
    return t;
}

bool holds(const SelectorTerm& t, const Point& p) {
    const double x = p[static_cast<std::size_t>(t.axis)];
    switch (t.compare) {
        case SelectorTerm::Compare::less:
            return x < t.value;
        case SelectorTerm::Compare::less_equal:
            return x <= t.value;
        case SelectorTerm::Compare::greater:
            return x > t.value;
        case SelectorTerm::Compare::greater_equal:
            return x >= t.value;
        case SelectorTerm::Compare::equal:
            return x == t.value;
    }
    return false;
}

}  // namespace

Outcome<VertexSelector> parse_vertex_selector(std::string_view text) {
    VertexSelector selector;
    selector.text = std::string(text);
    std::string_view rest = text;
    while (true) {
        const std::size_t amp = rest.find('&');
        const std::string_view term = trim(rest.substr(0, amp));
        std::variant<SelectorTerm, std::string> parsed = parse_term(term);
        if (const std::string* why = std::get_if<std::string>(&parsed))
            return Refusal{
                RefusalCode::bad_argument,
                "selector '" + std::string(text) + "': term '" + std::string(term) + "': " + *why};
        selector.terms.push_back(std::get<SelectorTerm>(parsed));
        if (amp == std::string_view::npos)
            break;
        rest.remove_prefix(amp + 1);
    }
    return selector;
}

std::vector<VertexId> select_vertices(const Mesh& mesh, const VertexSelector& selector) {
    const std::size_t n = mesh.vertex_count();
    // the vertices each set-valued term allows: in an element (always), on the boundary, in an
    // element of a label
    std::vector<char> allowed(n, 0);
    for (const ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        for (int j = 0; j < s.count(); ++j)
            allowed[s.vertex(j)] = 1;
    }
    for (const SelectorTerm& term : selector.terms) {
        if (term.kind == SelectorTerm::Kind::coordinate)
            continue;
        std::vector<char> in(n, 0);
        if (term.kind == SelectorTerm::Kind::boundary) {
            mesh.for_each_boundary_face([&](FaceId f) {
                const Simplex s = mesh.face_simplex(f);
                for (int j = 0; j < s.count(); ++j)
                    in[s.vertex(j)] = 1;
            });
        } else {
            for (const ElementId t : elements(mesh))
                if (mesh.label(t) == term.label) {
                    const Simplex& s = mesh.simplex(t);
                    for (int j = 0; j < s.count(); ++j)
                        in[s.vertex(j)] = 1;
                }
        }
        for (std::size_t v = 0; v < n; ++v)
            allowed[v] = static_cast<char>(allowed[v] && in[v]);
    }
    std::vector<VertexId> selected;
    for (VertexId v = 0; v < n; ++v) {
        if (!allowed[v])
            continue;
        const Point& p = mesh.reference(v);
        if (std::all_of(selector.terms.begin(), selector.terms.end(), [&](const SelectorTerm& t) {
                return t.kind != SelectorTerm::Kind::coordinate || holds(t, p);
            }))
            selected.push_back(v);
    }
    return selected;
}

}  // namespace sxk::elasticity
