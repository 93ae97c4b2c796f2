// SPDX-License-Identifier: Apache-2.0
// Every table of methods in the README and docs/*.md names every method of the registry, so
// that a new method fails here until it is documented. A table of methods is marked by the
// line before it: `<!-- method table: all -->` (every row) or `<!-- method table: images -->`
// (every row whose result is an image or a solid texture, i.e. that makes recipes). A
// table left unmarked whose rows start with three or more methods fails too.
#include <texsyn/methods.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace texsyn;

namespace {

// A Markdown table: its lines, where it starts, and the marker before it ("" if none).
struct Table {
    std::string file;
    size_t line = 0;
    std::string marker;
    std::vector<std::string> rows;
};

std::vector<Table> tables_of(const fs::path& path, const std::string& name)
{
    std::vector<Table> tables;
    std::ifstream in(path);
    std::string line, previous;
    bool inside = false;
    for (size_t n = 1; std::getline(in, line); ++n) {
        if (line.rfind("|", 0) == 0) {
            if (!inside) {
                static const std::regex marker("<!-- method table: ([a-z]+) -->");
                std::smatch m;
                tables.push_back({ name, n,
                    std::regex_search(previous, m, marker) ? m[1].str() : std::string(), {} });
            }
            tables.back().rows.push_back(line);
            inside = true;
        } else {
            inside = false;
            if (!line.empty())
                previous = line;
        }
    }
    return tables;
}

// Whether `text` names method `name` as `--name` or `name` in backquotes.
bool mentions(const std::string& text, const std::string& name)
{
    const std::regex re("(--" + name + "(?![a-z_-])|`" + name + "`)");
    return std::regex_search(text, re);
}

// Whether one of the first two cells of `row` starts with a method's name.
bool starts_with_method(const std::string& row)
{
    std::vector<std::string> cells;
    std::stringstream ss(row.substr(1));
    for (std::string cell; std::getline(ss, cell, '|') && cells.size() < 2;)
        cells.push_back(cell);
    for (const std::string& cell : cells)
        for (const Method* m : methods()) {
            static const std::regex lead("^ *\\[?`?(--)?");
            const std::string rest = std::regex_replace(cell, lead, "");
            if (rest.rfind(m->name, 0) == 0
                && (rest.size() == m->name.size()
                    || std::string("`[:] ").find(rest[m->name.size()]) != std::string::npos))
                return true;
        }
    return false;
}

std::vector<Table> every_table()
{
    const fs::path root = TEXSYN_SOURCE_DIR;
    std::vector<Table> tables = tables_of(root / "README.md", "README.md");
    for (const auto& entry : fs::directory_iterator(root / "docs"))
        if (entry.path().extension() == ".md") {
            const std::string name = "docs/" + entry.path().filename().string();
            for (Table& t : tables_of(entry.path(), name))
                tables.push_back(std::move(t));
        }
    return tables;
}

} // namespace

TEST(DocMethodTables, EveryMarkedTableNamesEveryMethod)
{
    std::set<std::string> marked_files;
    for (const Table& t : every_table()) {
        if (t.marker.empty())
            continue;
        SCOPED_TRACE(t.file + ":" + std::to_string(t.line));
        ASSERT_TRUE(t.marker == "all" || t.marker == "images") << t.marker;
        marked_files.insert(t.file);
        std::string text;
        for (const std::string& row : t.rows)
            text += row + "\n";
        for (const Method* m : methods()) {
            if (t.marker == "all" || m->makes_recipes()) {
                EXPECT_TRUE(mentions(text, m->name)) << "the table does not name " << m->name;
            }
        }
    }
    // The pages that tabulate methods keep their markers.
    for (const char* file : { "README.md", "docs/cli.md", "docs/which-method.md" })
        EXPECT_TRUE(marked_files.count(file)) << file << " has no marked table of methods";
}

TEST(DocMethodTables, UnmarkedTablesOfMethodsAreRefused)
{
    for (const Table& t : every_table()) {
        if (!t.marker.empty())
            continue;
        int method_rows = 0;
        for (const std::string& row : t.rows)
            method_rows += starts_with_method(row);
        EXPECT_LT(method_rows, 3) << t.file << ":" << t.line
                                  << ": a table of methods without a <!-- method table: all|images "
                                     "--> line before it";
    }
}
