#include "candela/content/diagnostics.h"

#include <algorithm>

namespace candela::content {

void Diagnostics::warning(std::string file, std::string element, std::string message) {
    messages.push_back(
        {Severity::Warning, std::move(file), std::move(element), std::move(message)});
}

void Diagnostics::error(std::string file, std::string element, std::string message) {
    messages.push_back({Severity::Error, std::move(file), std::move(element), std::move(message)});
}

bool Diagnostics::hasErrors() const {
    return count(Severity::Error) > 0;
}

std::size_t Diagnostics::count(Severity severity) const {
    return static_cast<std::size_t>(
        std::count_if(messages.begin(), messages.end(),
                      [severity](const Diagnostic& d) { return d.severity == severity; }));
}

bool Diagnostics::mentions(const std::string& needle) const {
    return std::any_of(messages.begin(), messages.end(), [&](const Diagnostic& d) {
        return formatDiagnostic(d).find(needle) != std::string::npos;
    });
}

std::string Diagnostics::toString() const {
    std::string text;
    for (const Diagnostic& d : messages) {
        text += formatDiagnostic(d);
        text += '\n';
    }
    return text;
}

std::string formatDiagnostic(const Diagnostic& d) {
    std::string line = d.file.empty() ? std::string("<memory>") : d.file;
    if (!d.element.empty()) line += ": " + d.element;
    line += d.severity == Severity::Error ? ": error: " : ": warning: ";
    line += d.message;
    return line;
}

}  // namespace candela::content
