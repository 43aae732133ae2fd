#include "IO/JsonText.h"

#include <algorithm>

namespace sgp
{

std::string DescribeJsonValue(const nlohmann::json& value)
{
  using Json = nlohmann::json;
  std::string dump = value.dump();
  if (dump.size() > 40)
    dump = dump.substr(0, 37) + "...";
  switch (value.type())
  {
    case Json::value_t::string:
      return "the string " + dump;
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "the number " + dump;
    case Json::value_t::boolean:
      return "the boolean " + dump;
    case Json::value_t::array:
      return "an array " + dump;
    case Json::value_t::object:
      return "an object " + dump;
    default:
      return "null";
  }
}

std::string JsonTypeWords(nlohmann::json::value_t type)
{
  using Json = nlohmann::json;
  switch (type)
  {
    case Json::value_t::number_float:
      return "a number";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::boolean:
      return "true or false";
    default:
      return "an object";
  }
}

std::string JsonMemberMismatch(const nlohmann::json& object, const std::string& key, nlohmann::json::value_t type)
{
  const auto it = object.find(key);
  if (it == object.end())
    return "is missing";
  const bool number = type == nlohmann::json::value_t::number_float && it->is_number();
  if (!number && it->type() != type)
    return "is " + DescribeJsonValue(*it);
  return "";
}

std::string UnknownJsonKey(const nlohmann::json& object, const std::vector<std::string>& allowed)
{
  for (const auto& item : object.items())
    if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
      return item.key();
  return "";
}

std::string JsonErrorMessage(const std::string& what)
{
  std::string message = what.substr(what.find(']') == std::string::npos ? 0 : what.find(']') + 2);
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}

} // namespace sgp
