#include "sextant/eval/sparsity.hpp"

#include <algorithm>
#include <cmath>

#include "sextant/core/atomic_file.hpp"
#include "svg_document.hpp"

namespace sextant {

namespace {

/// Grid dimensions and the cell of each matrix row/column.
SparsityGrid empty_grid(std::size_t rows, std::size_t cols, std::size_t max_side) {
  SparsityGrid g;
  g.rows = rows;
  g.cols = cols;
  max_side = std::max<std::size_t>(1, max_side);
  g.grid_rows = std::min(rows, max_side);
  g.grid_cols = std::min(cols, max_side);
  g.fill.assign(g.grid_rows * g.grid_cols, 0.0);
  return g;
}

std::size_t cell_of(std::size_t index, std::size_t size, std::size_t cells) {
  return index * cells / size;
}

/// Turns per-cell counts into fractions of each cell's area.
void normalise(SparsityGrid& g) {
  std::vector<double> row_span(g.grid_rows, 0.0), col_span(g.grid_cols, 0.0);
  for (std::size_t r = 0; r < g.rows; ++r) row_span[cell_of(r, g.rows, g.grid_rows)] += 1.0;
  for (std::size_t c = 0; c < g.cols; ++c) col_span[cell_of(c, g.cols, g.grid_cols)] += 1.0;
  for (std::size_t i = 0; i < g.grid_rows; ++i)
    for (std::size_t j = 0; j < g.grid_cols; ++j)
      g.fill[i * g.grid_cols + j] = std::min(1.0, g.fill[i * g.grid_cols + j] / (row_span[i] * col_span[j]));
}

/// Darkness in [0, 1] of a cell: any non-zero is clearly visible, a full cell is black.
double darkness(double fill) {
  return fill > 0.0 ? 0.3 + 0.7 * fill : 0.0;
}

void put_u32(std::string& out, unsigned long v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xFF);
}

void put_chunk(std::string& out, const char* type, const std::string& data) {
  put_u32(out, data.size());
  std::string body(type, 4);
  body += data;
  out += body;
  put_u32(out, crc32(reinterpret_cast<const unsigned char*>(body.data()), body.size()));
}

}  // namespace

SparsityGrid sparsity_grid(const Eigen::MatrixXd& matrix, double threshold, std::size_t max_side) {
  SparsityGrid g =
      empty_grid(static_cast<std::size_t>(matrix.rows()), static_cast<std::size_t>(matrix.cols()), max_side);
  if (g.rows == 0 || g.cols == 0) return g;
  for (std::size_t c = 0; c < g.cols; ++c) {  // column-major walk for Eigen's storage
    const std::size_t gc = cell_of(c, g.cols, g.grid_cols);
    for (std::size_t r = 0; r < g.rows; ++r) {
      const double v = matrix(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c));
      if (std::isnan(v) || std::abs(v) > threshold) {
        g.fill[cell_of(r, g.rows, g.grid_rows) * g.grid_cols + gc] += 1.0;
        ++g.nonzeros;
      }
    }
  }
  normalise(g);
  return g;
}

SparsityGrid sparsity_grid(std::size_t rows, std::size_t cols,
                           const std::vector<std::pair<std::size_t, std::size_t>>& entries,
                           std::size_t max_side) {
  SparsityGrid g = empty_grid(rows, cols, max_side);
  if (rows == 0 || cols == 0) return g;
  std::vector<std::pair<std::size_t, std::size_t>> unique;
  for (const auto& e : entries)
    if (e.first < rows && e.second < cols) unique.push_back(e);
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  for (const auto& [r, c] : unique)
    g.fill[cell_of(r, rows, g.grid_rows) * g.grid_cols + cell_of(c, cols, g.grid_cols)] += 1.0;
  g.nonzeros = unique.size();
  normalise(g);
  return g;
}

std::string render_sparsity_svg(const SparsityGrid& grid, const std::string& title, int size_px) {
  const double margin_top = 44, margin = 20, margin_bottom = 36;
  const std::size_t side = std::max<std::size_t>({grid.grid_rows, grid.grid_cols, 1});
  const double cell = static_cast<double>(size_px) / static_cast<double>(side);
  const double w = cell * grid.grid_cols, h = cell * grid.grid_rows;
  svg::Document doc(static_cast<int>(std::ceil(w + 2 * margin)),
                    static_cast<int>(std::ceil(h + margin_top + margin_bottom)));
  if (!title.empty()) doc.text(margin + w / 2, 24, title, 15, "middle");
  // One rectangle per run of equally dark cells in a row (8 shade levels).
  for (std::size_t i = 0; i < grid.grid_rows; ++i) {
    std::size_t j = 0;
    while (j < grid.grid_cols) {
      const int level = static_cast<int>(std::ceil(darkness(grid.at(i, j)) * 8.0));
      std::size_t end = j + 1;
      while (end < grid.grid_cols && static_cast<int>(std::ceil(darkness(grid.at(i, end)) * 8.0)) == level)
        ++end;
      if (level > 0) {
        const int gray = static_cast<int>(std::lround(255.0 * (1.0 - level / 8.0)));
        char color[8];
        std::snprintf(color, sizeof color, "#%02x%02x%02x", gray, gray, gray);
        doc.rect(margin + j * cell, margin_top + i * cell, (end - j) * cell, cell, color);
      }
      j = end;
    }
  }
  doc.rect(margin, margin_top, w, h, "none", "#444");
  doc.text(margin + w / 2, margin_top + h + 22,
           std::to_string(grid.rows) + " × " + std::to_string(grid.cols) + ", " +
               std::to_string(grid.nonzeros) + " non-zeros",
           12, "middle");
  return doc.finish();
}

GrayImage sparsity_image(const SparsityGrid& grid, std::size_t pixels_per_cell) {
  GrayImage img;
  pixels_per_cell = std::max<std::size_t>(1, pixels_per_cell);
  img.width = grid.grid_cols * pixels_per_cell;
  img.height = grid.grid_rows * pixels_per_cell;
  img.pixels.resize(img.width * img.height);
  for (std::size_t y = 0; y < img.height; ++y)
    for (std::size_t x = 0; x < img.width; ++x) {
      const double d = darkness(grid.at(y / pixels_per_cell, x / pixels_per_cell));
      img.pixels[y * img.width + x] = static_cast<unsigned char>(std::lround(255.0 * (1.0 - d)));
    }
  return img;
}

unsigned long crc32(const unsigned char* data, std::size_t size, unsigned long crc) {
  static const auto table = [] {
    std::vector<unsigned long> t(256);
    for (unsigned long n = 0; n < 256; ++n) {
      unsigned long c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320UL ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  crc ^= 0xFFFFFFFFUL;
  for (std::size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return (crc ^ 0xFFFFFFFFUL) & 0xFFFFFFFFUL;
}

unsigned long adler32(const unsigned char* data, std::size_t size) {
  unsigned long a = 1, b = 0;
  for (std::size_t i = 0; i < size; ++i) {
    a = (a + data[i]) % 65521;
    b = (b + a) % 65521;
  }
  return (b << 16) | a;
}

std::string encode_png(const GrayImage& image) {
  // An empty image becomes one white pixel (PNG needs width, height ≥ 1).
  GrayImage img = image;
  if (img.width == 0 || img.height == 0 || img.pixels.size() < img.width * img.height) {
    img.width = img.height = 1;
    img.pixels.assign(1, 255);
  }
  // Scanlines with filter type 0 (none).
  std::string raw;
  raw.reserve((img.width + 1) * img.height);
  for (std::size_t y = 0; y < img.height; ++y) {
    raw += '\0';
    raw.append(reinterpret_cast<const char*>(&img.pixels[y * img.width]), img.width);
  }
  // zlib stream: CMF/FLG (deflate, 32 K window, no dictionary; (0x78·256 + 0x01) % 31 = 0),
  // stored blocks of at most 65535 bytes, Adler-32 of the raw data.
  std::string z{'\x78', '\x01'};
  std::size_t pos = 0;
  do {
    const std::size_t len = std::min<std::size_t>(65535, raw.size() - pos);
    const bool last = pos + len == raw.size();
    z += static_cast<char>(last ? 1 : 0);
    z += static_cast<char>(len & 0xFF);
    z += static_cast<char>(len >> 8);
    z += static_cast<char>(~len & 0xFF);
    z += static_cast<char>((~len >> 8) & 0xFF);
    z.append(raw, pos, len);
    pos += len;
  } while (pos < raw.size());
  put_u32(z, adler32(reinterpret_cast<const unsigned char*>(raw.data()), raw.size()));

  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  put_u32(ihdr, img.width);
  put_u32(ihdr, img.height);
  ihdr +=
      std::string{'\x08', '\x00', '\x00', '\x00', '\x00'};  // 8-bit grayscale, deflate, no filter/interlace
  put_chunk(png, "IHDR", ihdr);
  put_chunk(png, "IDAT", z);
  put_chunk(png, "IEND", "");
  return png;
}

void write_png(const GrayImage& image, const std::filesystem::path& path) {
  write_file_atomically(path, encode_png(image));
}

}  // namespace sextant
