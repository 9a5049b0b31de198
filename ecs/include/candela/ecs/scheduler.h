#pragma once
// Runs systems once per frame. Each system declares the components and resources it reads
// and writes; within a phase the scheduler keeps declaration order between systems that
// conflict (one writes what the other reads or writes) and runs the rest in parallel on the
// job system. Phases run in order. Command buffers are applied at sync points: at the end of
// every phase and before every exclusive system (one that changes structure directly).
//
// While a stage of non-exclusive systems runs, the registry's structure is locked: a system
// that tries create/destroy/emplace/remove directly gets an EcsError; it should use
// ctx.commands(). Undeclared accesses are not detected: declare everything a system touches.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <candela/ecs/command_buffer.h>
#include <candela/ecs/job_system.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/resources.h>
#include <candela/ecs/view.h>

namespace candela::ecs {

enum class Phase : std::uint8_t {
    PreUpdate,   // input, time: resources the frame starts from
    Update,      // gameplay
    PostUpdate,  // derived state: transform propagation, bounds
    PreRender,   // extraction for the renderer (reads only, ideally)
};
inline constexpr std::size_t kPhaseCount = 4;
const char* phaseName(Phase phase) noexcept;

class Scheduler;

// What a running system gets.
class SystemContext {
public:
    Registry& registry() const noexcept { return *registry_; }
    JobSystem& jobs() const noexcept { return *jobs_; }
    std::string_view systemName() const noexcept;
    // This system's command buffer for the calling thread, applied at the next sync point.
    CommandBuffer& commands() const;

    // Runs view.each(fn) split in chunks over the job system. fn must only touch what the
    // system declared; writes to the visited components are safe (each entity is visited by
    // exactly one job).
    template <class ViewT, class F>
    void parallelEach(const ViewT& view, F&& fn, std::uint32_t rowsPerJob = 4096) const {
        const std::vector<ViewChunk> chunks = view.chunks(rowsPerJob);
        jobs_->parallelFor(chunks.size(), 1, [&](std::size_t begin, std::size_t end) {
            for (std::size_t c = begin; c < end; ++c)
                view.each(chunks[c], fn);
        });
    }

private:
    friend class Scheduler;
    SystemContext(Scheduler& scheduler, std::size_t system);
    Scheduler* scheduler_;
    Registry* registry_;
    JobSystem* jobs_;
    std::size_t system_;
};

using SystemFunction = std::function<void(SystemContext&)>;

class Scheduler {
public:
    // Declares a system's accesses: scheduler.addSystem(...).reads<Velocity>().writes<Position>()
    class SystemBuilder {
    public:
        template <Component... Ts>
        SystemBuilder& reads() {
            (add(componentKey(componentId<Ts>()), false), ...);
            return *this;
        }
        template <Component... Ts>
        SystemBuilder& writes() {
            (add(componentKey(componentId<Ts>()), true), ...);
            return *this;
        }
        template <class... Rs>
        SystemBuilder& readsResource() {
            (add(resourceKey(resourceId<Rs>()), false), ...);
            return *this;
        }
        template <class... Rs>
        SystemBuilder& writesResource() {
            (add(resourceKey(resourceId<Rs>()), true), ...);
            return *this;
        }
        // Runs alone after a sync point, with the structure unlocked: it may create, destroy,
        // add and remove directly.
        SystemBuilder& exclusive();

    private:
        friend class Scheduler;
        SystemBuilder(Scheduler& scheduler, std::size_t system)
            : scheduler_(&scheduler), system_(system) {}
        void add(std::uint64_t key, bool write);
        static std::uint64_t componentKey(ComponentId id) { return id; }
        static std::uint64_t resourceKey(std::uint32_t id) { return std::uint64_t{1} << 32 | id; }
        Scheduler* scheduler_;
        std::size_t system_;
    };

    // A group of systems that run together, then (if any follows) the next stage.
    struct Stage {
        Phase phase;
        bool exclusive;
        std::vector<std::size_t> systems;  // indices in declaration order
    };

    Scheduler(Registry& registry, JobSystem& jobs);
    ~Scheduler();
    Scheduler(const Scheduler&) = delete;
    Scheduler& operator=(const Scheduler&) = delete;

    SystemBuilder addSystem(std::string name, Phase phase, SystemFunction fn);

    // One frame: every phase in order, with sync points.
    void run();

    // The execution plan (rebuilt after systems are added).
    const std::vector<Stage>& stages();
    // The plan as text, one stage per line: "Update: move | spin" means move and spin run
    // in parallel; "(sync)" marks where command buffers are applied.
    std::string describe();
    std::string_view systemName(std::size_t system) const { return systems_[system].name; }
    Registry& registry() const noexcept { return *registry_; }
    JobSystem& jobs() const noexcept { return *jobs_; }

private:
    friend class SystemContext;
    struct Access {
        std::uint64_t key;
        bool write;
    };
    struct System {
        std::string name;
        Phase phase;
        SystemFunction fn;
        std::vector<Access> accesses;
        bool exclusive = false;
        std::vector<std::unique_ptr<CommandBuffer>> buffers;  // by job system thread index
    };

    static bool conflicts(const System& a, const System& b);
    void plan();
    void runStage(const Stage& stage);
    void runSystem(std::size_t system);
    void applyCommands();

    Registry* registry_;
    JobSystem* jobs_;
    std::vector<System> systems_;
    std::vector<Stage> stages_;
    bool planned_ = false;
};

}  // namespace candela::ecs
