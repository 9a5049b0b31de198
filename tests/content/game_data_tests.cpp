// Typed gameData: values of the asked type come back, anything else is empty with a message
// naming the key, and broken text is no crash.
#include <gtest/gtest.h>

#include "candela/content/game_data.h"

namespace candela::content {
namespace {

using Vec3Array = std::array<float, 3>;

TEST(GameData, TypedValuesComeBackAndNestedKeysReachIn) {
    GameDataReader data(GameData{
        R"({"role":"orbiter","speed":0.6,"points":3,"boss":true,"spawn":{"at":[1,2,-3.5]}})"});
    ASSERT_TRUE(data.isObject());
    EXPECT_EQ(data.get<std::string>("role"), "orbiter");
    EXPECT_FLOAT_EQ(*data.get<float>("speed"), 0.6f);
    EXPECT_EQ(data.get<int>("points"), 3);
    EXPECT_EQ(data.get<double>("points"), 3.0);
    EXPECT_EQ(data.get<bool>("boss"), true);
    EXPECT_EQ(data.get<Vec3Array>("spawn.at"), (Vec3Array{1, 2, -3.5f}));
    EXPECT_TRUE(data.has("spawn"));
    EXPECT_EQ(data.value("speed", 9.0f), 0.6f);
    EXPECT_EQ(data.value("missing", 9.0f), 9.0f);
    EXPECT_EQ(data.value<std::string>("role", ""), "orbiter");
}

TEST(GameData, WrongTypesAreEmptyAndTheProblemNamesTheKey) {
    GameDataReader data(std::string_view(R"({"speed":"fast","points":2.5,"at":[1,2]})"));
    EXPECT_FALSE(data.get<float>("speed"));
    EXPECT_EQ(data.problem<float>("speed"), "'speed' is a string, expected a number");
    EXPECT_FALSE(data.get<int>("points"));
    EXPECT_EQ(data.problem<int>("points"), "'points' is a number, expected an integer");
    EXPECT_FALSE((data.get<Vec3Array>("at")));
    EXPECT_EQ(data.problem<Vec3Array>("at"),
              "'at' is an array of 2, expected an array of 3 numbers");
    EXPECT_EQ(data.problem<bool>("nope.deeper"), "'nope.deeper' is missing");
    EXPECT_EQ(data.problem<std::string>("speed"), "");
}

TEST(GameData, TextThatIsNotAnObjectGivesNothing) {
    for (const char* text : {"", "not json", "[1,2]", "{\"a\":"}) {
        GameDataReader data{std::string_view(text)};
        EXPECT_FALSE(data.isObject()) << text;
        EXPECT_FALSE(data.get<int>("a")) << text;
        EXPECT_EQ(data.problem<int>("a"), "'a' is missing") << text;
    }
}

}  // namespace
}  // namespace candela::content
