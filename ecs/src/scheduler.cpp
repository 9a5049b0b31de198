#include <candela/ecs/scheduler.h>

#include <algorithm>

namespace candela::ecs {

const char* phaseName(Phase phase) noexcept {
    switch (phase) {
        case Phase::PreUpdate:
            return "PreUpdate";
        case Phase::Update:
            return "Update";
        case Phase::PostUpdate:
            return "PostUpdate";
        case Phase::PreRender:
            return "PreRender";
    }
    return "?";
}

SystemContext::SystemContext(Scheduler& scheduler, std::size_t system)
    : scheduler_(&scheduler),
      registry_(scheduler.registry_),
      jobs_(scheduler.jobs_),
      system_(system) {}

std::string_view SystemContext::systemName() const noexcept {
    return scheduler_->systems_[system_].name;
}

CommandBuffer& SystemContext::commands() const {
    // Each thread owns its slot; the slots were created before the stage started.
    return *scheduler_->systems_[system_].buffers[jobs_->threadIndex()];
}

Scheduler::SystemBuilder& Scheduler::SystemBuilder::exclusive() {
    scheduler_->systems_[system_].exclusive = true;
    scheduler_->planned_ = false;
    return *this;
}

void Scheduler::SystemBuilder::add(std::uint64_t key, bool write) {
    auto& accesses = scheduler_->systems_[system_].accesses;
    auto it = std::find_if(accesses.begin(), accesses.end(),
                           [&](const Access& a) { return a.key == key; });
    if (it == accesses.end()) {
        accesses.push_back(Access{key, write});
    } else {
        it->write = it->write || write;
    }
    scheduler_->planned_ = false;
}

Scheduler::Scheduler(Registry& registry, JobSystem& jobs) : registry_(&registry), jobs_(&jobs) {}

Scheduler::~Scheduler() = default;

Scheduler::SystemBuilder Scheduler::addSystem(std::string name, Phase phase, SystemFunction fn) {
    System system;
    system.name = std::move(name);
    system.phase = phase;
    system.fn = std::move(fn);
    for (unsigned t = 0; t < jobs_->threadCount(); ++t) {
        system.buffers.push_back(std::make_unique<CommandBuffer>(*registry_));
    }
    systems_.push_back(std::move(system));
    planned_ = false;
    return SystemBuilder(*this, systems_.size() - 1);
}

bool Scheduler::conflicts(const System& a, const System& b) {
    if (a.exclusive || b.exclusive) return true;
    for (const Access& x : a.accesses) {
        for (const Access& y : b.accesses) {
            if (x.key == y.key && (x.write || y.write)) return true;
        }
    }
    return false;
}

void Scheduler::plan() {
    stages_.clear();
    for (std::size_t p = 0; p < kPhaseCount; ++p) {
        const auto phase = static_cast<Phase>(p);
        // Each system goes one stage after the latest earlier system it conflicts with.
        std::vector<std::size_t> inPhase;
        std::vector<std::size_t> stageOf;
        std::size_t stageCount = 0;
        for (std::size_t s = 0; s < systems_.size(); ++s) {
            if (systems_[s].phase != phase) continue;
            std::size_t stage = 0;
            for (std::size_t i = 0; i < inPhase.size(); ++i) {
                if (conflicts(systems_[inPhase[i]], systems_[s])) {
                    stage = std::max(stage, stageOf[i] + 1);
                }
            }
            inPhase.push_back(s);
            stageOf.push_back(stage);
            stageCount = std::max(stageCount, stage + 1);
        }
        std::vector<Stage> phaseStages(stageCount, Stage{phase, false, {}});
        for (std::size_t i = 0; i < inPhase.size(); ++i) {
            Stage& stage = phaseStages[stageOf[i]];
            stage.systems.push_back(inPhase[i]);
            stage.exclusive = stage.exclusive || systems_[inPhase[i]].exclusive;
        }
        for (Stage& stage : phaseStages)
            stages_.push_back(std::move(stage));
    }
    planned_ = true;
}

const std::vector<Scheduler::Stage>& Scheduler::stages() {
    if (!planned_) plan();
    return stages_;
}

std::string Scheduler::describe() {
    std::string out;
    const std::vector<Stage>& all = stages();
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Stage& stage = all[i];
        if (stage.exclusive) out += "(sync)\n";
        out += phaseName(stage.phase);
        out += stage.exclusive ? " exclusive: " : ": ";
        for (std::size_t k = 0; k < stage.systems.size(); ++k) {
            if (k > 0) out += " | ";
            out += systems_[stage.systems[k]].name;
        }
        out += '\n';
        if (i + 1 == all.size() || all[i + 1].phase != stage.phase) out += "(sync)\n";
    }
    return out;
}

void Scheduler::runSystem(std::size_t system) {
    SystemContext context(*this, system);
    systems_[system].fn(context);
}

void Scheduler::runStage(const Stage& stage) {
    if (stage.exclusive) {
        applyCommands();  // the exclusive system sees every change recorded before it
        runSystem(stage.systems.front());
        return;
    }
    const Registry::StructureLock lock(*registry_);
    if (stage.systems.size() == 1) {
        runSystem(stage.systems.front());
        return;
    }
    JobSystem::WaitGroup group;
    for (std::size_t k = 1; k < stage.systems.size(); ++k) {
        const std::size_t system = stage.systems[k];
        jobs_->run(group, [this, system] { runSystem(system); });
    }
    // The calling thread takes the first system, then helps with the rest.
    std::exception_ptr error;
    try {
        runSystem(stage.systems.front());
    } catch (...) {
        error = std::current_exception();
    }
    jobs_->wait(group);
    if (error) std::rethrow_exception(error);
}

void Scheduler::applyCommands() {
    // Declaration order, then thread order: the same recording gives the same result.
    for (System& system : systems_) {
        for (auto& buffer : system.buffers) {
            if (!buffer->empty()) buffer->apply();
        }
    }
}

void Scheduler::run() {
    if (!planned_) plan();
    for (std::size_t i = 0; i < stages_.size(); ++i) {
        runStage(stages_[i]);
        if (i + 1 == stages_.size() || stages_[i + 1].phase != stages_[i].phase) {
            applyCommands();  // sync point at the end of each phase
        }
    }
}

}  // namespace candela::ecs
