// YAML to JSON over libyaml's document model.
#include "yaml_json.h"

#include <yaml.h>

#include <regex>
#include <set>

#include "common/json_writer.h"

namespace relmap::robot {
namespace {

// Anchors may make a node its own descendant; no config nests this deep.
constexpr int kMaxDepth = 64;

std::string_view ScalarOf(const yaml_node_t& node) {
  return {reinterpret_cast<const char*>(node.data.scalar.value), node.data.scalar.length};
}

std::string PlainScalarJson(std::string_view value) {
  static const std::regex kJsonNumber(R"(-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  if (value == "true" || value == "false") return std::string(value);
  if (value.empty() || value == "~" || value == "null" || value == "Null" || value == "NULL") {
    return "null";
  }
  if (std::regex_match(value.begin(), value.end(), kJsonNumber)) return std::string(value);
  return client::JsonQuoted(value);
}

class Converter {
 public:
  Converter(yaml_document_t& document, const std::string& label)
      : document_(document), label_(label) {}

  Status Append(const yaml_node_t& node, int depth, std::string* json) {
    if (depth > kMaxDepth) return Invalid(node, "nested more than 64 deep (an anchor cycle?)");
    switch (node.type) {
      case YAML_SCALAR_NODE:
        *json += node.data.scalar.style == YAML_PLAIN_SCALAR_STYLE
                     ? PlainScalarJson(ScalarOf(node))
                     : client::JsonQuoted(ScalarOf(node));
        return OkStatus();
      case YAML_SEQUENCE_NODE: {
        *json += '[';
        for (const yaml_node_item_t* item = node.data.sequence.items.start;
             item < node.data.sequence.items.top; ++item) {
          if (item != node.data.sequence.items.start) *json += ',';
          if (Status s = Append(*yaml_document_get_node(&document_, *item), depth + 1, json);
              !s.ok()) {
            return s;
          }
        }
        *json += ']';
        return OkStatus();
      }
      case YAML_MAPPING_NODE: {
        *json += '{';
        std::set<std::string_view> keys;
        for (const yaml_node_pair_t* pair = node.data.mapping.pairs.start;
             pair < node.data.mapping.pairs.top; ++pair) {
          const yaml_node_t& key = *yaml_document_get_node(&document_, pair->key);
          if (key.type != YAML_SCALAR_NODE) return Invalid(key, "a key is not a plain name");
          if (!keys.insert(ScalarOf(key)).second) {
            return Invalid(key, "key \"" + std::string(ScalarOf(key)) + "\" appears twice");
          }
          if (pair != node.data.mapping.pairs.start) *json += ',';
          *json += client::JsonQuoted(ScalarOf(key)) + ':';
          if (Status s = Append(*yaml_document_get_node(&document_, pair->value), depth + 1, json);
              !s.ok()) {
            return s;
          }
        }
        *json += '}';
        return OkStatus();
      }
      case YAML_NO_NODE:
        break;
    }
    *json += "null";
    return OkStatus();
  }

 private:
  Status Invalid(const yaml_node_t& node, const std::string& what) const {
    return InvalidArgumentError(label_ + ":" + std::to_string(node.start_mark.line + 1) + ": " +
                                what);
  }

  yaml_document_t& document_;
  const std::string& label_;
};

// libyaml's parser and its documents, released on every path.
struct Parser {
  Parser() { yaml_parser_initialize(&parser); }
  ~Parser() { yaml_parser_delete(&parser); }
  Status Load(yaml_document_t* document, const std::string& label) {
    if (yaml_parser_load(&parser, document)) return OkStatus();
    return InvalidArgumentError(
        label + ":" + std::to_string(parser.problem_mark.line + 1) +
        ": not valid YAML: " + (parser.problem != nullptr ? parser.problem : "unknown error") +
        (parser.context != nullptr ? std::string(" ") + parser.context : ""));
  }
  yaml_parser_t parser;
};

struct Document {
  ~Document() {
    if (loaded) yaml_document_delete(&document);
  }
  yaml_document_t document{};
  bool loaded = false;
};

}  // namespace

StatusOr<std::string> YamlToJson(std::string_view yaml, const std::string& label) {
  Parser parser;
  yaml_parser_set_input_string(&parser.parser, reinterpret_cast<const unsigned char*>(yaml.data()),
                               yaml.size());
  Document first;
  if (Status s = parser.Load(&first.document, label); !s.ok()) return s;
  first.loaded = true;
  const yaml_node_t* root = yaml_document_get_root_node(&first.document);
  if (root == nullptr) return InvalidArgumentError(label + ": the YAML file is empty");
  Document second;
  if (Status s = parser.Load(&second.document, label); !s.ok()) return s;
  second.loaded = true;
  if (yaml_document_get_root_node(&second.document) != nullptr) {
    return InvalidArgumentError(label + ": more than one YAML document (\"---\"); a config is one");
  }
  std::string json;
  if (Status s = Converter(first.document, label).Append(*root, 0, &json); !s.ok()) return s;
  return json;
}

}  // namespace relmap::robot
