#include "candela/content/game_data.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace candela::content {

struct GameDataReader::Parsed {
    nlohmann::json root;
};

namespace {

using nlohmann::json;

// The value at "a.b.c" (members of nested objects), or null when any step is missing.
const json* find(const json& root, std::string_view key) {
    const json* at = &root;
    while (true) {
        if (!at->is_object()) return nullptr;
        const size_t dot = key.find('.');
        auto it = at->find(std::string(key.substr(0, dot)));
        if (it == at->end()) return nullptr;
        at = &*it;
        if (dot == std::string_view::npos) return at;
        key.remove_prefix(dot + 1);
    }
}

bool finiteFloat(const json& j) {
    return j.is_number() && std::isfinite(j.get<double>()) &&
           std::fabs(j.get<double>()) <= std::numeric_limits<float>::max();
}

// What T is called in problem messages, and whether `j` holds one.
template <class T>
struct Kind;
template <>
struct Kind<bool> {
    static constexpr const char* name = "true or false";
    static bool holds(const json& j) { return j.is_boolean(); }
    static bool read(const json& j) { return j.get<bool>(); }
};
template <>
struct Kind<int> {
    static constexpr const char* name = "an integer";
    static bool holds(const json& j) {
        return j.is_number_integer() && j.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
               j.get<std::int64_t>() <= std::numeric_limits<int>::max();
    }
    static int read(const json& j) { return int(j.get<std::int64_t>()); }
};
template <>
struct Kind<float> {
    static constexpr const char* name = "a number";
    static bool holds(const json& j) { return finiteFloat(j); }
    static float read(const json& j) { return float(j.get<double>()); }
};
template <>
struct Kind<double> {
    static constexpr const char* name = "a number";
    static bool holds(const json& j) { return j.is_number() && std::isfinite(j.get<double>()); }
    static double read(const json& j) { return j.get<double>(); }
};
template <>
struct Kind<std::string> {
    static constexpr const char* name = "a string";
    static bool holds(const json& j) { return j.is_string(); }
    static std::string read(const json& j) { return j.get<std::string>(); }
};
template <>
struct Kind<std::array<float, 3>> {
    static constexpr const char* name = "an array of 3 numbers";
    static bool holds(const json& j) {
        return j.is_array() && j.size() == 3 && finiteFloat(j[0]) && finiteFloat(j[1]) &&
               finiteFloat(j[2]);
    }
    static std::array<float, 3> read(const json& j) {
        return {float(j[0].get<double>()), float(j[1].get<double>()), float(j[2].get<double>())};
    }
};

std::string typeName(const json& j) {
    if (j.is_boolean()) return "true or false";
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_array()) return "an array of " + std::to_string(j.size());
    if (j.is_object()) return "an object";
    return "null";
}

}  // namespace

GameDataReader::GameDataReader(const GameData& data) : GameDataReader(data.json) {}

GameDataReader::GameDataReader(std::string_view text) : parsed_(std::make_unique<Parsed>()) {
    parsed_->root = json::parse(text.begin(), text.end(), nullptr, false);
}

GameDataReader::~GameDataReader() = default;
GameDataReader::GameDataReader(GameDataReader&&) noexcept = default;
GameDataReader& GameDataReader::operator=(GameDataReader&&) noexcept = default;

bool GameDataReader::isObject() const {
    return parsed_->root.is_object();
}

bool GameDataReader::has(std::string_view key) const {
    return find(parsed_->root, key) != nullptr;
}

template <class T>
std::optional<T> GameDataReader::get(std::string_view key) const {
    const json* j = find(parsed_->root, key);
    if (!j || !Kind<T>::holds(*j)) return std::nullopt;
    return Kind<T>::read(*j);
}

template <class T>
std::string GameDataReader::problem(std::string_view key) const {
    const json* j = find(parsed_->root, key);
    if (!j) return "'" + std::string(key) + "' is missing";
    if (Kind<T>::holds(*j)) return {};
    return "'" + std::string(key) + "' is " + typeName(*j) + ", expected " + Kind<T>::name;
}

#define CANDELA_GAME_DATA_TYPE(T)                                             \
    template std::optional<T> GameDataReader::get<T>(std::string_view) const; \
    template std::string GameDataReader::problem<T>(std::string_view) const;
CANDELA_GAME_DATA_TYPE(bool)
CANDELA_GAME_DATA_TYPE(int)
CANDELA_GAME_DATA_TYPE(float)
CANDELA_GAME_DATA_TYPE(double)
CANDELA_GAME_DATA_TYPE(std::string)
using Float3Array = std::array<float, 3>;
CANDELA_GAME_DATA_TYPE(Float3Array)
#undef CANDELA_GAME_DATA_TYPE

}  // namespace candela::content
