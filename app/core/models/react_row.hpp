#pragma once

#include "core/models/reaction_model.hpp"

namespace morphogen {

// ReactionModel::react() for a model with a Cell (see reaction_model.hpp), so
// each reaction is written once in C++. Kept out of reaction_model.hpp because
// the GL and CLI code that includes that header is built without OpenMP.
template <class Cell> void reactRow(const RowView& row, const float* params) {
    constexpr int n = Cell::kChemicals;
    const Cell cell(params);
#pragma omp simd
    for (int i = 0; i < row.n; ++i) {
        float c[n], dcdt[n];
        for (int k = 0; k < n; ++k)
            c[k] = row.c[k][i];
        cell.react(c, dcdt);
        for (int k = 0; k < n; ++k)
            row.dcdt[k][i] = dcdt[k];
    }
}

} // namespace morphogen
