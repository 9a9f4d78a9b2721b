#pragma once
// The sparsity image of a matrix (e.g. the SEIF information matrix, 3000×3000): the matrix is
// downsampled into a grid of at most max_side × max_side cells, each holding the fraction of
// its entries that are non-zero; the grid renders as an SVG (filled cells) or a grayscale PNG.
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace sextant {

struct SparsityGrid {
  std::size_t rows = 0, cols = 0;            ///< of the original matrix
  std::size_t grid_rows = 0, grid_cols = 0;  ///< cells
  std::vector<double> fill;                  ///< row-major, fraction of non-zeros per cell in [0, 1]
  std::size_t nonzeros = 0;

  double at(std::size_t r, std::size_t c) const { return fill[r * grid_cols + c]; }
};

/// |m(r, c)| > threshold counts as non-zero (NaN counts as non-zero: it is not structurally zero).
SparsityGrid sparsity_grid(const Eigen::MatrixXd& matrix, double threshold = 0.0, std::size_t max_side = 300);
/// From a list of non-zero (row, col) entries of a rows × cols matrix (out-of-range entries ignored).
SparsityGrid sparsity_grid(std::size_t rows, std::size_t cols,
                           const std::vector<std::pair<std::size_t, std::size_t>>& entries,
                           std::size_t max_side = 300);

/// SVG with one filled square per non-empty cell (darker = fuller), runs merged per row.
std::string render_sparsity_svg(const SparsityGrid& grid, const std::string& title, int size_px = 600);

/// 8-bit grayscale pixels (black = full) of the grid, one pixel per cell, scaled by an integer
/// factor `pixels_per_cell`.
struct GrayImage {
  std::size_t width = 0, height = 0;
  std::vector<unsigned char> pixels;  ///< row-major, top row first
};
GrayImage sparsity_image(const SparsityGrid& grid, std::size_t pixels_per_cell = 1);

/// A PNG file image (8-bit grayscale, zlib stored blocks, CRC-32 and Adler-32) as bytes.
std::string encode_png(const GrayImage& image);
/// Encodes and writes atomically.
void write_png(const GrayImage& image, const std::filesystem::path& path);

/// CRC-32 (PNG / zlib polynomial) and Adler-32, exposed for tests.
unsigned long crc32(const unsigned char* data, std::size_t size, unsigned long crc = 0);
unsigned long adler32(const unsigned char* data, std::size_t size);

}  // namespace sextant
