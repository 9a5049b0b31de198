#pragma once
// Typed reads of an entity's free-form gameData (a scene file's "gameData" object), without a
// JSON library in the game:
//
//   candela::content::GameDataReader data(registry.get<GameData>(e));
//   float speed = data.value("speed", 1.0f);            // the fallback when absent or mistyped
//   std::string role = data.value<std::string>("role", "");
//   if (auto spawn = data.get<std::array<float, 3>>("spawn.at")) ...   // nested: "a.b"
//
// get<T> is empty when the key is absent or holds another type; problem(key) says which, for
// an error message that names the key. T: bool, int, float, double, std::string,
// std::array<float, 3>.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "candela/content/components/scene_components.h"

namespace candela::content {

class GameDataReader {
public:
    explicit GameDataReader(const GameData& data);
    explicit GameDataReader(std::string_view json);
    ~GameDataReader();
    GameDataReader(GameDataReader&&) noexcept;
    GameDataReader& operator=(GameDataReader&&) noexcept;

    // False when the text is not a JSON object (every get is then empty).
    bool isObject() const;
    bool has(std::string_view key) const;

    template <class T>
    std::optional<T> get(std::string_view key) const;
    template <class T>
    T value(std::string_view key, T fallback) const {
        return get<T>(key).value_or(std::move(fallback));
    }

    // Empty when get<T>(key) would succeed, else e.g. "'speed' is missing" or "'speed' is a
    // string, expected a number".
    template <class T>
    std::string problem(std::string_view key) const;

private:
    struct Parsed;
    std::unique_ptr<Parsed> parsed_;
};

}  // namespace candela::content
