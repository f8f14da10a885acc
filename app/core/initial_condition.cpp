#include "core/initial_condition.hpp"

#include <cmath>

#include "core/random.hpp"
#include "core/reaction_model.hpp"

namespace morphogen {

std::string toString(InitialCondition::Type type) {
    switch (type) {
    case InitialCondition::Type::Noise:
        return "noise";
    case InitialCondition::Type::CentreSquare:
        return "centre_square";
    case InitialCondition::Type::SeedSpots:
        return "seed_spots";
    }
    return "noise";
}

namespace {
float lookup(const std::map<std::string, float>& values, const std::string& key, float fallback) {
    auto it = values.find(key);
    return it == values.end() ? fallback : it->second;
}
} // namespace

State makeInitialState(const InitialCondition& init, const ReactionModel& model,
                       const std::map<std::string, float>& params, int width, int height,
                       std::uint64_t seed) {
    const int channels = int(model.chemicals().size());
    State state(width, height, channels);

    // Which cells take the `inside` values.
    std::vector<unsigned char> marked(state.cellCount(), 0);
    if (init.type == InitialCondition::Type::CentreSquare) {
        const int side =
            std::max(1, int(std::lround(init.squareFraction * std::min(width, height))));
        const int x0 = (width - side) / 2, y0 = (height - side) / 2;
        for (int y = y0; y < y0 + side; ++y)
            for (int x = x0; x < x0 + side; ++x)
                marked[std::size_t(y) * width + x] = 1;
    } else if (init.type == InitialCondition::Type::SeedSpots) {
        const float r = init.spotRadius;
        const int reach = int(std::ceil(r));
        for (int s = 0; s < init.spotCount; ++s) {
            // Streams 2000+ are the spot centres, apart from the per-cell noise.
            const int cx = int(uniform01(seed, 2000, 2 * s) * width);
            const int cy = int(uniform01(seed, 2000, 2 * s + 1) * height);
            for (int dy = -reach; dy <= reach; ++dy)
                for (int dx = -reach; dx <= reach; ++dx) {
                    if (float(dx * dx + dy * dy) > r * r)
                        continue;
                    // Spots wrap around the edges, as a periodic grid would.
                    const int x = ((cx + dx) % width + width) % width;
                    const int y = ((cy + dy) % height + height) % height;
                    marked[std::size_t(y) * width + x] = 1;
                }
        }
    }

    for (int c = 0; c < channels; ++c) {
        const std::string& name = model.chemicals()[std::size_t(c)].name;
        const float base = lookup(init.base, name, 0.0f);
        const float inside = lookup(init.inside, name, base);
        const float noise = lookup(init.noise, name, 0.0f);
        float* plane = state.plane(c);
        for (std::size_t i = 0; i < state.cellCount(); ++i) {
            const float value = marked[i] ? inside : base;
            plane[i] = noise == 0.0f
                           ? value
                           : float(value + noise * uniformSigned(seed, std::uint64_t(c), i));
        }
    }
    model.prepareState(state, params, seed);
    return state;
}

} // namespace morphogen
