#include "cli/help_format.h"

#include <algorithm>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace pathcl::cli {
namespace {

constexpr std::size_t kPageWidth = 100;   // columns a help line fills at most
constexpr std::size_t kNameColumn = 30;   // where descriptions start (CLI11's default)
constexpr std::size_t kExampleIndent = 6; // of an example's explanation, under its command

// `text` broken into lines of at most `width` characters at spaces (a longer word stays
// whole), joined by '\n' + `indent`.
std::string wrapped(const std::string& text, std::size_t width, const std::string& indent = "")
{
    std::istringstream words(text);
    std::string out, line, word;
    while (words >> word) {
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            out += (out.empty() ? "" : "\n" + indent) + line;
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + (line.empty() ? "" : (out.empty() ? "" : "\n" + indent) + line);
}

class HelpFormatter : public CLI::Formatter {
public:
    explicit HelpFormatter(std::vector<std::string> group_order) : group_order_(std::move(group_order))
    {
        column_width(kNameColumn);
        label("Subcommands", "Commands");
        label("SUBCOMMAND", "COMMAND");
    }

    std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override
    {
        if (mode == CLI::AppFormatMode::Sub)
            return make_expanded(app);
        std::string out = make_description(app) + make_usage(app, name) + make_positionals(app);
        std::vector<std::string> groups = group_order_;
        for (const std::string& g : app->get_groups())
            if (std::find(groups.begin(), groups.end(), g) == groups.end())
                groups.push_back(g); // "Options": --help, and any option left out of the groups
        for (const std::string& group : groups) {
            std::vector<const CLI::Option*> options = app->get_options(
                [&](const CLI::Option* opt) { return opt->get_group() == group && opt->nonpositional(); });
            if (!group.empty() && !options.empty())
                out += make_group(group, false, options); // "\nGroup:\n" and its options
        }
        return out + make_subcommands(app, mode) + "\n" + make_footer(app);
    }

    std::string make_option_desc(const CLI::Option* opt) const override
    {
        return wrapped(opt->get_description(), kPageWidth - kNameColumn);
    }

    std::string make_subcommand(const CLI::App* sub) const override
    {
        std::stringstream out;
        CLI::detail::format_help(out, sub->get_name(), wrapped(sub->get_description(), kPageWidth - kNameColumn),
                                 kNameColumn);
        return out.str();
    }

private:
    std::vector<std::string> group_order_;
};

std::string examples_text(const std::vector<HelpExample>& examples)
{
    if (examples.empty())
        return "";
    const std::string indent(kExampleIndent, ' ');
    std::string text = "Examples:";
    for (const HelpExample& e : examples)
        text += "\n  " + e.command + "\n" + indent + wrapped(e.what, kPageWidth - kExampleIndent, indent);
    return text;
}

} // namespace

void describe_command(CLI::App* command, const std::vector<HelpGroup>& groups, const std::vector<HelpExample>& examples)
{
    std::vector<std::string> order;
    for (const HelpGroup& g : groups) {
        order.push_back(g.name);
        for (const std::string& flag : g.options) {
            CLI::Option* opt = command->get_option_no_throw(flag);
            if (!opt)
                throw std::logic_error("help group " + g.name + " names " + flag + ", which pathcl " +
                                       command->get_name() + " does not have");
            opt->group(g.name);
        }
    }
    command->formatter(std::make_shared<HelpFormatter>(std::move(order)));
    command->footer(examples_text(examples));
}

void use_help_format(CLI::App& app, const std::vector<HelpExample>& examples)
{
    app.formatter(std::make_shared<HelpFormatter>(std::vector<std::string>{}));
    app.footer(examples_text(examples));
}

} // namespace pathcl::cli
