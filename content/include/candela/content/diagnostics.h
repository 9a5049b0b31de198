#pragma once
// Messages produced while loading content. Loaders never throw or abort on bad input; they
// record what went wrong here and continue where they can, so one bad primitive or texture
// costs only that element.
#include <string>
#include <vector>

namespace candela::content {

enum class Severity { Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;     // the file being loaded
    std::string element;  // e.g. "meshes[3].primitives[0]"; empty when it concerns the whole file
    std::string message;  // what is wrong and, where it matters, what was done instead
};

struct Diagnostics {
    std::vector<Diagnostic> messages;

    void warning(std::string file, std::string element, std::string message);
    void error(std::string file, std::string element, std::string message);

    bool hasErrors() const;
    std::size_t count(Severity severity) const;
    // True when any message's text contains `needle` (tests and tools search messages).
    bool mentions(const std::string& needle) const;
    // One line per message: "file: element: error: message".
    std::string toString() const;
};

std::string formatDiagnostic(const Diagnostic& diagnostic);

}  // namespace candela::content
