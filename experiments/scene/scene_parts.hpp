// The parts a scene run is made of, listed in one place: which emitter a scene's [emitter]
// kind makes, and which observers watch the run (an observer of an effect the scene leaves off
// is not made, and costs nothing). A new emitter or observer is one new file and one line here.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "experiments/scene/emitter.hpp"
#include "experiments/scene/observer.hpp"
#include "experiments/scene/scene.hpp"

namespace rice::experiments {

std::unique_ptr<Emitter> make_emitter(const Scene& scene);

/// When the scene drops its grains as a block: 0 for the clump emitter; for a fill whose mould
/// is held above the ground when it goes (a cup), the mould's removal; none otherwise (a
/// mould standing on the ground, whatever its frame's origin).
std::optional<double> drop_time(const Scene& scene);

/// The observers of a run writing into `folder`, in the order they are called.
std::vector<std::unique_ptr<Observer>> make_observers(const Scene& scene, const std::filesystem::path& folder);

}  // namespace rice::experiments
