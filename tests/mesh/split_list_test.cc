// SplitList (ergo/mesh/split_list.h): the documented cases, and the same fields as the
// std::getline loops it replaced for every string of separators and letters up to length 5.
#include "ergo/mesh/split_list.h"

#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace ergo {
namespace {

using Fields = std::vector<std::string>;

TEST(Mesh, SplitListKeepsFieldsAsWritten) {
  EXPECT_EQ(SplitList("tx,tz", ','), (Fields{"tx", "tz"}));
  EXPECT_EQ(SplitList("tx", ','), (Fields{"tx"}));
  EXPECT_EQ(SplitList(" a , b ", ','), (Fields{" a ", " b "}));  // not trimmed
  EXPECT_EQ(SplitList("0.03;0.01", ';'), (Fields{"0.03", "0.01"}));
  EXPECT_EQ(SplitList("a,b;c", ';'), (Fields{"a,b", "c"}));  // only the separator given
}

TEST(Mesh, SplitListEmptyFieldsAndTheTrailingSeparator) {
  EXPECT_EQ(SplitList("", ','), Fields{});
  EXPECT_EQ(SplitList(",", ','), (Fields{""}));
  EXPECT_EQ(SplitList(",,", ','), (Fields{"", ""}));
  EXPECT_EQ(SplitList(",a", ','), (Fields{"", "a"}));
  EXPECT_EQ(SplitList("a,,b", ','), (Fields{"a", "", "b"}));
  EXPECT_EQ(SplitList("a,b,", ','), (Fields{"a", "b"}));  // the separator ends "b"
  EXPECT_EQ(SplitList("a,b,,", ','), (Fields{"a", "b", ""}));
  EXPECT_EQ(SplitList(" ", ','), (Fields{" "}));
}

TEST(Mesh, SplitListMatchesTheGetlineLoopsItReplaced) {
  const std::string alphabet = ",a ";
  std::vector<std::string> texts = {""};
  for (int length = 1; length <= 5; ++length) {
    std::vector<std::string> longer;
    for (const std::string& text : texts) {
      if (static_cast<int>(text.size()) != length - 1) continue;
      for (char c : alphabet) longer.push_back(text + c);
    }
    texts.insert(texts.end(), longer.begin(), longer.end());
  }
  for (const std::string& text : texts) {
    Fields getline;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');) getline.push_back(item);
    EXPECT_EQ(SplitList(text, ','), getline) << "'" << text << "'";
  }
}

}  // namespace
}  // namespace ergo
