// ctess animate: one SVG per frame while the factors move from one triple to another, plus an index.html
// flip-book, so a person can watch a transition and see that nothing pops.
#include "cli_args.hpp"
#include "commands.hpp"
#include "file_output.hpp"
#include "mesh.hpp"
#include "mesh_formats.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

std::string flip_book_html(unsigned frames, const std::string& title,
                           const std::vector<std::string>& captions) {
    std::string list;
    for (unsigned i = 0; i < frames; ++i) list += fmt::format("{}\"{}\"", i ? "," : "", captions[i]);
    return fmt::format(R"(<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{0}</title>
<style>
 body {{ font-family: DejaVu Sans, Helvetica, Arial, sans-serif; margin: 20px; color: #1b2838; }}
 #controls {{ display: flex; gap: 12px; align-items: center; margin: 8px 0; }}
 input[type=range] {{ width: 420px; }}
 img {{ border: 1px solid #ccd; }}
</style></head>
<body>
<h2>{0}</h2>
<div id="controls">
 <button id="play">Play</button>
 <input id="slider" type="range" min="0" max="{1}" value="0">
 <span id="label"></span>
</div>
<img id="frame" src="frame_000.svg" width="720" height="700" alt="tessellation frame">
<p>Drag the slider or press Play. Keys: left/right step one frame, space plays/pauses.</p>
<script>
const captions = [{2}];
const img = document.getElementById('frame'), slider = document.getElementById('slider');
const label = document.getElementById('label'), play = document.getElementById('play');
const pad = (i) => String(i).padStart(3, '0');
function show(i) {{ slider.value = i; img.src = 'frame_' + pad(i) + '.svg'; label.textContent = captions[i]; }}
let timer = null;
function toggle() {{
  if (timer) {{ clearInterval(timer); timer = null; play.textContent = 'Play'; return; }}
  play.textContent = 'Pause';
  timer = setInterval(() => show((+slider.value + 1) % {3}), 120);
}}
slider.oninput = () => show(+slider.value);
play.onclick = toggle;
document.onkeydown = (e) => {{
  if (e.key === 'ArrowRight') show(Math.min({1}, +slider.value + 1));
  if (e.key === 'ArrowLeft') show(Math.max(0, +slider.value - 1));
  if (e.key === ' ') {{ e.preventDefault(); toggle(); }}
}};
show(0);
</script>
</body></html>
)",
                       title, frames - 1, list, frames);
}

// The flip-book's size bound, checked before the first frame is written (issue: 256,256,256 with 1,000
// frames would be about 12 GB).
constexpr std::uint64_t max_animation_bytes = std::uint64_t{512} << 20;

} // namespace

int run_animate(int argc, char** argv) {
    const Args args(
        argc, argv, 2,
        {"mode", "domain", "from", "to", "frames", "out", "winding", "max", "layout", "column-rule"},
        {"provoking"});
    PatternRequest r = pattern_request_from(args, "from");
    const std::vector<float> from = r.factors;
    const std::vector<float> to = parse_float_list(args.get("to"), "--to", from.size(), from.size());
    require_usable_factors(to, "--to");
    const unsigned frames = parse_unsigned(args.get("frames"), "--frames", 2, 1000);
    const std::string dir = args.get("out");

    auto frame_svg = [&](const std::string& caption) {
        return mesh_to_svg(tessellate(r), r, SvgOptions{args.has("provoking"), caption});
    };
    auto frame_at = [&](unsigned i, std::string& caption) {
        const double s = double(i) / (frames - 1);
        for (std::size_t k = 0; k < from.size(); ++k)
            r.factors[k] = static_cast<float>(from[k] + (double(to[k]) - from[k]) * s);
        caption = fmt::format("frame {} of {}: factors ({})", i + 1, frames, factors_text(r.factors));
        return frame_svg(caption);
    };
    // Counts grow with every factor, and each factor moves linearly, so the frame of every factor's larger
    // end bounds every frame's size; a middle frame can mix the ends (1,1,256 to 256,256,1) and exceed both.
    std::string caption;
    for (std::size_t k = 0; k < from.size(); ++k) r.factors[k] = std::max(from[k], to[k]);
    const std::uint64_t bounding_frame =
        frame_svg(fmt::format("frame {} of {}: factors ({})", frames, frames, factors_text(r.factors)))
            .size();
    const std::uint64_t largest_frame = std::max({bounding_frame, std::uint64_t{frame_at(0, caption).size()},
                                                  std::uint64_t{frame_at(frames - 1, caption).size()}});
    if (largest_frame * frames > max_animation_bytes)
        throw UsageError(fmt::format(
            "{} frames of up to {:.1f} MB would write about {:.1f} MB; the limit is {} MiB: "
            "use fewer --frames or smaller factors",
            frames, largest_frame / 1e6, largest_frame * double(frames) / 1e6, max_animation_bytes >> 20));
    make_directory(dir);

    std::vector<std::string> captions;
    for (unsigned i = 0; i < frames; ++i) {
        const std::string svg = frame_at(i, caption);
        write_text(fmt::format("{}/frame_{:03}.svg", dir, i), svg);
        captions.push_back(caption);
    }
    const std::string title =
        fmt::format("ctess animate · {} · ({}) → ({})", r.mode, factors_text(from), factors_text(to));
    write_text(dir + "/index.html", flip_book_html(frames, title, captions));
    fmt::print("wrote {} frames and {}/index.html\n", frames, dir);
    return 0;
}

} // namespace ctess::cli
