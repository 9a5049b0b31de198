#pragma once
// What a runtime system reads and writes, declared when it is added:
//
//   app.addSystem("patrol", ecs::Phase::Update, patrol).reads<Hazard>().writes<LocalTransform>();
//
// The application runs its systems on an ecs::Scheduler (ecs/scheduler.h): systems whose
// declared sets do not conflict (neither writes what the other reads or writes) run in
// parallel; conflicting ones run in the order they were added. A declared system runs while
// the registry's structure is locked: creating, destroying, adding or removing components
// throws ecs::EcsError; such systems are added exclusive (the addSystem(name, fn) overload).
// Undeclared accesses are not detected: declare everything a system touches.
#include <functional>
#include <vector>

#include "candela/ecs/scheduler.h"

namespace candela::runtime {

class SystemDeclaration {
public:
    template <ecs::Component... Ts>
    SystemDeclaration& reads() {
        declare_.push_back([](ecs::Scheduler::SystemBuilder& b) { b.reads<Ts...>(); });
        return *this;
    }
    template <ecs::Component... Ts>
    SystemDeclaration& writes() {
        declare_.push_back([](ecs::Scheduler::SystemBuilder& b) { b.writes<Ts...>(); });
        return *this;
    }
    template <class... Rs>
    SystemDeclaration& readsResource() {
        declare_.push_back([](ecs::Scheduler::SystemBuilder& b) { b.readsResource<Rs...>(); });
        return *this;
    }
    template <class... Rs>
    SystemDeclaration& writesResource() {
        declare_.push_back([](ecs::Scheduler::SystemBuilder& b) { b.writesResource<Rs...>(); });
        return *this;
    }
    // Runs alone with the structure unlocked (conflicts with every other system).
    SystemDeclaration& exclusive() {
        declare_.push_back([](ecs::Scheduler::SystemBuilder& b) { b.exclusive(); });
        return *this;
    }

    // Replays the declaration onto a scheduler's system (the application rebuilds its
    // scheduler when the world is replaced).
    void applyTo(ecs::Scheduler::SystemBuilder& builder) const {
        for (const auto& declare : declare_)
            declare(builder);
    }

private:
    std::vector<std::function<void(ecs::Scheduler::SystemBuilder&)>> declare_;
};

}  // namespace candela::runtime
