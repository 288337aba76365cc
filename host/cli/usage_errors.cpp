#include "cli/usage_errors.h"

#include <algorithm>
#include <cctype>
#include <iterator>

#include "common/error.h"

namespace pathcl::cli {
namespace {

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// Optimal string alignment distance: Levenshtein's, with a swap of two neighbours as one
// edit ("--widht" is one from "--width").
std::size_t edit_distance(const std::string& a, const std::string& b)
{
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i)
        d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j)
        d[0][j] = j;
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t substitution = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[n][m];
}

std::string without_dashes(const std::string& s)
{
    return s.substr(std::min(s.find_first_not_of('-'), s.size()));
}

// An argument that names a flag ("--spp", "-o", "--spp=4"), not a value such as "-1".
bool is_flag(const std::string& arg)
{
    return arg.size() > 1 && arg[0] == '-' && !std::isdigit(static_cast<unsigned char>(arg[1])) && arg[1] != '.';
}

// Every flag name of `command` ("-o", "--output", ...), in the order they were added.
std::vector<std::string> flag_names(const CLI::App& command)
{
    std::vector<std::string> names;
    for (const CLI::Option* opt : command.get_options()) {
        for (const std::string& s : opt->get_snames())
            names.push_back("-" + s);
        for (const std::string& l : opt->get_lnames())
            names.push_back("--" + l);
    }
    return names;
}

std::vector<std::string> command_names(const CLI::App& app)
{
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (!sub->get_name().empty())
            names.push_back(sub->get_name());
    return names;
}

// The command being parsed when the error came: the last command named on the line.
const CLI::App& innermost_command(const CLI::App& app)
{
    const CLI::App* command = &app;
    for (;;) {
        const CLI::App* next = nullptr;
        for (const CLI::App* sub : command->get_subcommands())
            if (!sub->get_name().empty())
                next = sub;
        if (!next)
            return *command;
        command = next;
    }
}

std::string joined(const std::vector<std::string>& names, const char* last)
{
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? last : ", ") + names[i];
    return text;
}

} // namespace

std::vector<std::string> nearest_names(const std::string& typed, const std::vector<std::string>& names)
{
    const std::string key = lowercase(typed);
    auto begins_with_typed = [&](const std::string& name) { return lowercase(name).rfind(key, 0) == 0; };
    const std::size_t allowed = std::clamp<std::size_t>(without_dashes(typed).size() / 3, 1, 3);
    std::size_t best = allowed;
    std::vector<std::string> nearest;
    for (const std::string& name : names) {
        const std::size_t d = edit_distance(key, lowercase(name));
        if (d > best)
            continue;
        if (d < best)
            nearest.clear();
        best = d;
        nearest.push_back(name);
    }
    // Of names equally near, those that continue the typed one ("--sp": --spp, not --up).
    if (std::any_of(nearest.begin(), nearest.end(), begins_with_typed))
        std::erase_if(nearest, [&](const std::string& name) { return !begins_with_typed(name); });
    if (nearest.empty() && without_dashes(typed).size() >= 3)
        std::copy_if(names.begin(), names.end(), std::back_inserter(nearest), begins_with_typed);
    nearest.resize(std::min<std::size_t>(nearest.size(), 3));
    return nearest;
}

std::string did_you_mean(const std::vector<std::string>& names)
{
    return names.empty() ? "" : "; did you mean " + joined(names, " or ") + "?";
}

std::string usage_error(const CLI::App& app, const CLI::ParseError& error)
{
    // CLI11 checks required options before it reports the arguments it did not expect, but
    // a misspelt flag is the better report: it is often the required one (--outptu).
    const bool extras_error = dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr;
    if (extras_error || (dynamic_cast<const CLI::RequiredError*>(&error) && !app.remaining(true).empty())) {
        const std::vector<std::string> extras = app.remaining(true);
        const CLI::App& command = innermost_command(app);
        const std::string name = command.get_parent() ? command.get_name() : "pathcl";
        if (&command == &app && !extras.empty() && !is_flag(extras.front())) {
            const std::vector<std::string> commands = command_names(app);
            const std::vector<std::string> near = nearest_names(extras.front(), commands);
            return quote(extras.front()) + ": no such command" +
                   (near.empty() ? " (" + joined(commands, " or ") + ")" : did_you_mean(near));
        }
        for (const std::string& arg : extras)
            if (is_flag(arg)) {
                const std::string flag = arg.substr(0, arg.find('='));
                const std::vector<std::string> near = nearest_names(flag, flag_names(command));
                const std::string help = command.get_parent() ? "'pathcl " + name + " --help'" : "'pathcl --help'";
                const std::string shown = flag.size() <= kMaxQuotedBytes ? flag : quote(flag);
                return shown + ": " + name + " has no such flag" +
                       (near.empty() ? " (" + help + " lists them)" : did_you_mean(near));
            }
        if (!extras.empty())
            return name + ": unexpected argument " + quote(extras.front());
    }
    return one_line(error.what());
}

} // namespace pathcl::cli
