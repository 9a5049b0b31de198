#include "function_spans.h"

#include <cctype>
#include <string>

namespace candela::style {
namespace {

// `source` with comments, literals and preprocessor lines blanked (newlines kept).
std::string codeOnly(std::string_view source) {
    std::string out(source);
    size_t i = 0;
    bool lineStart = true;
    while (i < out.size()) {
        const char c = out[i];
        if (lineStart && c == '#') {  // a directive, with its continuations
            while (i < out.size() && out[i] != '\n') {
                if (out[i] == '\\' && i + 1 < out.size() && out[i + 1] == '\n') out[i++] = ' ';
                out[i++] = ' ';
            }
            continue;
        }
        if (c == '\n') {
            lineStart = true;
            ++i;
            continue;
        }
        if (!std::isspace(static_cast<unsigned char>(c))) lineStart = false;
        if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n')
                out[i++] = ' ';
        } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
            const size_t end = out.find("*/", i + 2);
            const size_t stop = end == std::string::npos ? out.size() : end + 2;
            for (; i < stop; ++i)
                if (out[i] != '\n') out[i] = ' ';
        } else if (c == 'R' && i + 1 < out.size() && out[i + 1] == '"') {  // raw string
            const size_t open = out.find('(', i);
            const std::string close = ")" + out.substr(i + 2, open - i - 2) + "\"";
            const size_t end = out.find(close, open);
            const size_t stop = end == std::string::npos ? out.size() : end + close.size();
            for (; i < stop; ++i)
                if (out[i] != '\n') out[i] = ' ';
        } else if (c == '"' || (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(
                                                            out[i - 1]))))) {  // not 1'000
            out[i++] = ' ';
            while (i < out.size() && out[i] != c && out[i] != '\n') {
                if (out[i] == '\\') out[i++] = ' ';
                if (i < out.size()) out[i++] = ' ';
            }
            if (i < out.size() && out[i] == c) out[i++] = ' ';
        } else {
            ++i;
        }
    }
    return out;
}

enum class Scope { Namespace, Class, Function, Block };

bool isWordChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

std::string trimmed(const std::string& text) {
    const size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// Where the whole word `word` last stands in `text`, or npos.
size_t lastWord(const std::string& text, std::string_view word) {
    for (size_t at = text.rfind(word); at != std::string::npos;
         at = at == 0 ? std::string::npos : text.rfind(word, at - 1)) {
        const size_t end = at + word.size();
        if ((at == 0 || !isWordChar(text[at - 1])) &&
            (end == text.size() || !isWordChar(text[end])))
            return at;
    }
    return std::string::npos;
}

// (No std::regex: GCC 12's <regex> trips -Wmaybe-uninitialized in sanitizer builds.)
Scope scopeOf(const std::string& rawHead, Scope enclosing) {
    if (enclosing == Scope::Function || enclosing == Scope::Block) return Scope::Block;
    const std::string head = trimmed(rawHead);
    if (head.starts_with("namespace") || head.starts_with("inline namespace") || head == "extern") {
        return Scope::Namespace;
    }
    // `struct X : Base {`, `enum class E : uint8_t {`: a type keyword and no parentheses after
    // it (`template <class T> T f(T x) {` has them).
    for (std::string_view keyword : {"class", "struct", "union", "enum"}) {
        const size_t at = lastWord(head, keyword);
        if (at != std::string::npos && head.find_first_of("()", at) == std::string::npos) {
            return Scope::Class;
        }
    }
    const size_t paren = head.find('(');
    if (head.find(')') == std::string::npos) return Scope::Block;  // `T x{...}`, `= {`
    if (head.find("operator") != std::string::npos) return Scope::Function;
    // `T x = f(...) {` cannot be a definition; `auto f = [](...) {` is data holding a lambda.
    const size_t equals = head.find('=');
    if (equals != std::string::npos && equals < paren) return Scope::Block;
    return Scope::Function;
}

}  // namespace

std::vector<FunctionSpan> functionSpans(std::string_view source) {
    const std::string code = codeOnly(source);
    struct Open {
        Scope scope;
        int firstLine;
        std::string head;
    };
    std::vector<Open> open;
    std::vector<FunctionSpan> spans;
    size_t headStart = 0;  // just after the last ; { or }
    int line = 1;
    std::vector<int> lineAt;  // line of each offset, filled as we go
    lineAt.reserve(code.size());
    for (size_t i = 0; i < code.size(); ++i) {
        lineAt.push_back(line);
        const char c = code[i];
        if (c == '\n') ++line;
        if (c == ';') {
            headStart = i + 1;
        } else if (c == '{') {
            const std::string head = code.substr(headStart, i - headStart);
            const Scope enclosing = open.empty() ? Scope::Namespace : open.back().scope;
            const Scope scope = scopeOf(head, enclosing);
            size_t first = headStart;
            while (first < i && std::isspace(static_cast<unsigned char>(code[first])))
                ++first;
            std::string firstHeadLine = code.substr(first, code.find('\n', first) - first);
            open.push_back({scope, lineAt[first], firstHeadLine});
            headStart = i + 1;
        } else if (c == '}') {
            if (!open.empty()) {
                const Open o = open.back();
                open.pop_back();
                if (o.scope == Scope::Function) {
                    spans.push_back({o.head, o.firstLine, line - o.firstLine + 1});
                }
            }
            headStart = i + 1;
        }
    }
    return spans;
}

}  // namespace candela::style
