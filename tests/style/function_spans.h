#pragma once
// Where the functions of a C++ source are and how long they are, from its braces alone: enough
// to hold a module to a function-length limit without a compiler front end. Comments, string
// and character literals and preprocessor lines are skipped; a brace whose head (the text since
// the previous `;`, `{` or `}`) has a parameter list and sits directly in a namespace or class
// opens a function body; lambdas and blocks inside it count toward that function.
#include <string>
#include <string_view>
#include <vector>

namespace candela::style {

struct FunctionSpan {
    std::string head;   // the signature's first line, trimmed
    int firstLine = 0;  // 1-based: where the signature starts
    int lines = 0;      // from the signature's first line to the closing brace
};

std::vector<FunctionSpan> functionSpans(std::string_view source);

}  // namespace candela::style
