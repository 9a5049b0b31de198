// Module shape limits that reviews keep asking for, checked on every build: no function in
// render/ runs past 150 lines (a reader holds a function in view; the frame's declaration once
// grew to 900).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "function_spans.h"

namespace candela::style {
namespace {

constexpr int kMaxFunctionLines = 150;

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(FunctionSpans, FindsFunctionsAndTheirLengths) {
    const std::string source = R"(#include <x>
namespace a {
struct S {
    int f() const {
        return 1;  // a } in a comment
    }
    bool b{false};
};
template <class T>
T twice(T x) {
    const char* s = "{ not a brace";
    auto l = [](int y) { return y; };
    return x + x + l(1);
}
constexpr int kTable[] = {1, 2, 3};
}  // namespace a
)";
    const std::vector<FunctionSpan> spans = functionSpans(source);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_EQ(spans[0].firstLine, 4);
    EXPECT_EQ(spans[0].lines, 3);
    EXPECT_EQ(spans[1].firstLine, 9);  // the template line starts the signature
    EXPECT_EQ(spans[1].lines, 6);
}

TEST(FunctionSpans, CountsAMultiLineSignatureAndInitializerList) {
    const std::string source =
        "Foo::Foo(int a,\n         int b)\n    : a_(a),\n      b_(b) {\n    run();\n}\n";
    const std::vector<FunctionSpan> spans = functionSpans(source);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_EQ(spans[0].firstLine, 1);
    EXPECT_EQ(spans[0].lines, 6);
}

TEST(FunctionSpans, ALongFunctionIsMeasuredInFull) {
    std::string source = "void longOne() {\n";
    for (int i = 0; i < 200; ++i)
        source += "    step(" + std::to_string(i) + ");\n";
    source += "}\n";
    const std::vector<FunctionSpan> spans = functionSpans(source);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_EQ(spans[0].lines, 202);
}

TEST(ModuleShape, NoRenderFunctionIsLongerThan150Lines) {
    const std::filesystem::path render = std::filesystem::path(CANDELA_SOURCE_DIR) / "render";
    int files = 0;
    std::string tooLong;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(render)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
        ++files;
        for (const FunctionSpan& f : functionSpans(readFile(entry.path()))) {
            if (f.lines <= kMaxFunctionLines) continue;
            tooLong += "  " + std::filesystem::relative(entry.path(), render).string() + ":" +
                       std::to_string(f.firstLine) + " (" + std::to_string(f.lines) +
                       " lines): " + f.head + "\n";
        }
    }
    EXPECT_GT(files, 100);  // the walk found the module
    EXPECT_TRUE(tooLong.empty()) << "functions in render/ over " << kMaxFunctionLines
                                 << " lines; split them:\n"
                                 << tooLong;
}

}  // namespace
}  // namespace candela::style
