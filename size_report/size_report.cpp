// size_report: entries and bytes of every compile-time CP table, for max factor 64 and 256, as a table or
// (--json) as [{"max_tess_factor", "tables": [{"name", "entries", "bytes"}], "total_bytes"}].
//
// The figures come from the table types; they are checked against the symbol sizes that nm reports for the
// compiled table objects (exit status 1 on any difference), so the report cannot drift from the binary.
// With the bare-metal toolchain the Cortex-M4 flash footprint (text + rodata) of runtime + tables follows.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <ctess/runtime/cp/table_integrity.hpp>
#include <ctess/runtime/cp/table_set.hpp>

#include "cp/table_objects.hpp"
#include "uniform/table_objects.hpp"

namespace {

namespace tables = ctess::cp::tables;

struct Table {
    std::string name;
    std::size_t entries;
    std::size_t bytes;
};

struct TableObject { // one emitted object and the tables it holds
    std::string symbol;
    std::size_t size;
    std::vector<Table> tables;
};

struct Config {
    unsigned max_factor;
    std::vector<TableObject> objects;
    std::string object_paths;
    std::string family = "cp"; // or "uniform"
};

template <class A>
Table table(const char* name, const A& array) {
    return {name, array.size(), sizeof(array)};
}

template <class Chunk>
TableObject column_object(const Chunk& c, const std::string& symbol) {
    return {symbol, sizeof(c), {table("column records", c.records), table("column starts", c.pool)}};
}

template <unsigned Max>
std::vector<TableObject> token_and_gap(const tables::TokenTable<Max>& tok, const tables::GapTable<Max>& gap) {
    return {{fmt::format("token_table_{}", Max),
             sizeof(tok),
             {table("token records", tok.records), table("token points", tok.point)}},
            {fmt::format("gap_table_{}", Max),
             sizeof(gap),
             {table("gap offsets", gap.offset), table("gap words", gap.word),
              table("gap T1 fans", gap.t1_last_fan)}}};
}

template <unsigned Max>
Config uniform_config(const ctess::uniform::tables::UniformTables<Max>& t, const char* paths) {
    return {Max,
            {{fmt::format("uniform_table_{}", Max),
              sizeof(t),
              {table("uniform offsets", t.offsets), table("uniform interior", t.interior),
               table("uniform indices", t.indices), table("uniform copy words", t.copy_words),
               table("uniform copy sources", t.copy_sources)}}},
            paths,
            "uniform"};
}

std::vector<Config> configs() {
    namespace d = ctess::rt::detail;
    Config c64{64, token_and_gap(d::token_table_64, d::gap_table_64), CTESS_TABLE_OBJECTS_64};
    c64.objects.push_back(column_object(d::column_chunk_64_0, "column_chunk_64_0"));
    Config c256{256, token_and_gap(d::token_table_256, d::gap_table_256), CTESS_TABLE_OBJECTS_256};
#define CTESS_REPORT_CHUNK_256(k)                                                                            \
    c256.objects.push_back(column_object(d::column_chunk_256_##k, "column_chunk_256_" #k));
    CTESS_FOR_EACH_COLUMN_CHUNK_256(CTESS_REPORT_CHUNK_256)
#undef CTESS_REPORT_CHUNK_256
    return {c64, c256, uniform_config(d::uniform_table_11, CTESS_UNIFORM_TABLE_OBJECTS_11),
            uniform_config(d::uniform_table_16, CTESS_UNIFORM_TABLE_OBJECTS_16)};
}

// The merged rows of a configuration (column chunks summed) and the total.
std::vector<Table> merged(const Config& c, std::size_t& total) {
    std::vector<Table> rows;
    total = 0;
    for (const TableObject& o : c.objects) {
        total += o.size;
        for (const Table& t : o.tables) {
            bool found = false;
            for (Table& r : rows) {
                if (r.name == t.name) {
                    r.entries += t.entries, r.bytes += t.bytes, found = true;
                }
            }
            if (!found) rows.push_back(t);
        }
    }
    return rows;
}

std::vector<std::string> split_bar(const std::string& s) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (at <= s.size()) {
        const std::size_t bar = s.find('|', at);
        const std::size_t end = bar == std::string::npos ? s.size() : bar;
        if (end > at) out.push_back(s.substr(at, end - at));
        at = end + 1;
    }
    return out;
}

std::string run(const std::string& command) {
    std::string out;
    FILE* p = popen(command.c_str(), "r");
    if (p == nullptr) return out;
    char buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    pclose(p);
    return out;
}

// nm -S sizes of the ctess::rt::detail symbols defined in the given objects.
std::map<std::string, std::size_t> symbol_sizes(const std::string& objects) {
    std::map<std::string, std::size_t> sizes;
    for (const std::string& obj : split_bar(objects)) {
        const std::string text = run(fmt::format("'{}' -S -C '{}'", CTESS_NM, obj));
        std::size_t at = 0;
        while (at < text.size()) {
            const std::size_t eol = text.find('\n', at);
            const std::string line = text.substr(at, eol == std::string::npos ? std::string::npos : eol - at);
            at = eol == std::string::npos ? text.size() : eol + 1;
            char size_hex[32] = {}, type[4] = {}, name[512] = {};
            if (std::sscanf(line.c_str(), "%*s %31s %3s %511s", size_hex, type, name) == 3) {
                const std::string prefix = "ctess::rt::detail::";
                const std::string n(name);
                if (n.rfind(prefix, 0) == 0 && (type[0] == 'R' || type[0] == 'r'))
                    sizes[n.substr(prefix.size())] = std::strtoull(size_hex, nullptr, 16);
            }
        }
    }
    return sizes;
}

// Every table object has exactly its type's size in .rodata, and its tables fill it up to alignment padding.
bool verify(const Config& c, std::string& why) {
    const auto sizes = symbol_sizes(c.object_paths);
    for (const TableObject& o : c.objects) {
        const auto it = sizes.find(o.symbol);
        if (it == sizes.end()) {
            why = fmt::format("{}: no read-only symbol in the table objects", o.symbol);
            return false;
        }
        if (it->second != o.size) {
            why = fmt::format("{}: nm says {} bytes, the type says {}", o.symbol, it->second, o.size);
            return false;
        }
        std::size_t sum = 0;
        for (const Table& t : o.tables) sum += t.bytes;
        if (sum > o.size || o.size - sum >= 8) {
            why = fmt::format("{}: the tables add up to {} bytes of {}", o.symbol, sum, o.size);
            return false;
        }
    }
    return true;
}

struct Flash {
    bool available = false;
    std::size_t tables = 0, runtime = 0, program = 0;
    std::size_t verify = 0; // verify_tables' code and nibble table (arm_verify_probe.cpp)
    // The runnable image that tests/embedded runs under QEMU (m4_run.cpp: CpPatch, UniformPatch,
    // UniformSplit, verify_tables, newlib's printf): flash = text + data, RAM = data + bss (mostly its output
    // buffers).
    std::size_t run_flash = 0, run_ram = 0;
};

// text + rodata of the Cortex-M4 objects: the tables, the runtime (probe and the CpPatch sources), and the
// linked program.
Flash flash([[maybe_unused]] unsigned max_factor) {
    Flash f;
#ifdef CTESS_ARM_SIZE
    const std::string objects = max_factor == 64 ? CTESS_ARM_OBJECTS_64 : CTESS_ARM_OBJECTS_256;
    const std::string elf = max_factor == 64 ? CTESS_ARM_ELF_64 : CTESS_ARM_ELF_256;
    for (const std::string& obj : split_bar(objects)) {
        const std::string text = run(fmt::format("'{}' -A '{}'", CTESS_ARM_SIZE, obj));
        std::size_t sum = 0, at = 0;
        while (at < text.size()) {
            const std::size_t eol = text.find('\n', at);
            const std::string line = text.substr(at, eol == std::string::npos ? std::string::npos : eol - at);
            at = eol == std::string::npos ? text.size() : eol + 1;
            char name[512] = {};
            unsigned long long size = 0;
            if (std::sscanf(line.c_str(), "%511s %llu", name, &size) == 2 &&
                (std::strncmp(name, ".text", 5) == 0 || std::strncmp(name, ".rodata", 7) == 0))
                sum += size;
        }
        // Object names are the sources' stems (size_report/CMakeLists.txt): runtime/src/cp/tables_*.cpp and
        // the column chunks' cp_tables_256_columns_k wrappers are tables; cp/patch_*.cpp and the probe
        // runtime.
        const std::string stem = obj.substr(obj.find_last_of('/') + 1);
        if (stem.find("tables_") != std::string::npos)
            f.tables += sum;
        else if (stem.starts_with("cp_runtime_probe") || stem.starts_with("patch_"))
            f.runtime += sum;
        else if (stem.starts_with("arm_verify_probe"))
            f.verify += sum;
    }
    unsigned long long text = 0, data = 0;
    const std::string berkeley = run(fmt::format("'{}' '{}'", CTESS_ARM_SIZE, elf));
    const std::size_t nl = berkeley.find('\n');
    if (nl != std::string::npos && std::sscanf(berkeley.c_str() + nl + 1, "%llu %llu", &text, &data) == 2) {
        f.program = text;
        f.available = f.tables > 0;
    }
    unsigned long long bss = 0;
    const std::string run_elf = max_factor == 64 ? CTESS_ARM_RUN_ELF_64 : CTESS_ARM_RUN_ELF_256;
    const std::string run_berkeley = run(fmt::format("'{}' '{}'", CTESS_ARM_SIZE, run_elf));
    const std::size_t run_nl = run_berkeley.find('\n');
    if (run_nl != std::string::npos &&
        std::sscanf(run_berkeley.c_str() + run_nl + 1, "%llu %llu %llu", &text, &data, &bss) == 3) {
        f.run_flash = text + data;
        f.run_ram = data + bss;
    }
#endif
    return f;
}

// verify_tables on one table set: its result, the fastest of 50 runs on this machine, and the bytes its
// compile-time data adds to the tables (the digest and each chunk's CRC constant).
struct Integrity {
    bool ok = false;
    double microseconds = 0;
    std::size_t data_bytes = 0;
};

Integrity integrity(unsigned max_factor) {
    const ctess::rt::CpTableSet& t = max_factor == 64 ? ctess::rt::cp_tables_64 : ctess::rt::cp_tables_256;
    Integrity r;
    r.ok = static_cast<bool>(ctess::rt::verify_tables(t));
    double best = 1e30;
    for (int run = 0; run < 50; ++run) {
        const auto start = std::chrono::steady_clock::now();
        const volatile bool ok = static_cast<bool>(ctess::rt::verify_tables(t));
        (void)ok;
        best = std::min(
            best,
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    }
    r.microseconds = best;
    r.data_bytes = sizeof(ctess::rt::CpTableDigest) + t.digest->chunks * sizeof(std::uint32_t);
    return r;
}

} // namespace

int main(int argc, char** argv) {
    const bool json = argc > 1 && std::strcmp(argv[1], "--json") == 0;
    const std::vector<Config> all = configs();
    bool ok = true;
    std::string report = json ? "[" : "";
    for (std::size_t k = 0; k < all.size(); ++k) {
        const Config& c = all[k];
        std::size_t total = 0;
        const std::vector<Table> rows = merged(c, total);
        std::string why;
        const bool verified = verify(c, why);
        ok = ok && verified;
        const Flash f = c.family == "cp" ? flash(c.max_factor) : Flash{};
        const Integrity check = c.family == "cp" ? integrity(c.max_factor) : Integrity{true, 0, 0};
        ok = ok && check.ok;
        if (json) {
            report += fmt::format("{}\n  {{\"family\": \"{}\", \"max_tess_factor\": {}, \"tables\": [",
                                  k ? "," : "", c.family, c.max_factor);
            for (std::size_t r = 0; r < rows.size(); ++r)
                report += fmt::format("{}\n    {{\"name\": \"{}\", \"entries\": {}, \"bytes\": {}}}",
                                      r ? "," : "", rows[r].name, rows[r].entries, rows[r].bytes);
            report +=
                fmt::format("], \"total_bytes\": {}, \"verified_against_objects\": {}", total, verified);
            if (f.available)
                report += fmt::format(
                    ", \"cortex_m4_flash\": {{\"tables\": {}, \"runtime\": {}, \"program_text\": {}, "
                    "\"verify_tables\": {}, \"run_image_flash\": {}, \"run_image_ram\": {}}}",
                    f.tables, f.runtime, f.program, f.verify, f.run_flash, f.run_ram);
            if (c.family == "cp")
                report += fmt::format(
                    ", \"verify_tables\": {{\"ok\": {}, \"microseconds\": {:.1f}, \"data_bytes\": {}}}",
                    check.ok, check.microseconds, check.data_bytes);
            report += "}";
        } else {
            report +=
                fmt::format("{}max_tess_factor {}\n  {:<20} {:>9} {:>9}\n",
                            c.family == "cp" ? "" : "uniform ", c.max_factor, "table", "entries", "bytes");
            for (const Table& t : rows)
                report += fmt::format("  {:<20} {:>9} {:>9}\n", t.name, t.entries, t.bytes);
            report += fmt::format("  {:<20} {:>9} {:>9}  ({:.1f} KiB, with alignment padding)\n", "total", "",
                                  total, static_cast<double>(total) / 1024.0);
            report += verified ? "  checked: every table object's nm size equals its type's size\n"
                               : fmt::format("  CHECK FAILED: {}\n", why);
            if (c.family != "cp") {
            } else if (f.available)
                report += fmt::format(
                    "  Cortex-M4 (-Os, thumb, no exceptions/RTTI), text + rodata: tables {} B, runtime "
                    "{} B; linked bare-metal program text {} B\n"
                    "  Cortex-M4 runnable image (m4_run, QEMU mps2-an386): flash {} B, RAM {} B\n",
                    f.tables, f.runtime, f.program, f.run_flash, f.run_ram);
            else
                report += "  Cortex-M4 footprint: not built (install gcc-arm-none-eabi, "
                          "libstdc++-arm-none-eabi-newlib)\n";
            if (c.family == "cp")
                report += fmt::format(
                    "  verify_tables: {}, {:.1f} us on this machine (fastest of 50); {} B of digest "
                    "and CRC constants{}\n",
                    check.ok ? "ok" : "FAILED (the tables differ from their compile-time CRC)",
                    check.microseconds, check.data_bytes,
                    f.available ? fmt::format(", {} B of Cortex-M4 code and CRC table", f.verify)
                                : std::string());
        }
    }
    report += json ? "\n]\n" : "";
    fmt::print("{}", report);
    return ok ? 0 : 1;
}
