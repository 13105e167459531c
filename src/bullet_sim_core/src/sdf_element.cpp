#include "bullet_sim_core/sdf_element.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <locale>
#include <sstream>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Strict and locale-independent: the whole word must be a finite number (a leading '+' is allowed).
bool toDouble(const std::string& word, double& out) {
  const char* b = word.data();
  const char* e = b + word.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, out);
  return b != e && r.ec == std::errc() && r.ptr == e && std::isfinite(out);
}

// One step of a path: "<sensor name='lidar'>", "<gazebo reference='laser'>", "<plugin name='p' filename='f'>".
std::string describe(const XMLElement* e) {
  std::string s = std::string("<") + e->Name();
  for (const char* attribute : {"name", "reference", "filename"})
    if (const char* v = e->Attribute(attribute)) s += std::string(" ") + attribute + "='" + v + "'";
  return s + ">";
}

std::string pathTo(const XMLElement* e) {
  std::string path;
  for (; e; e = e->Parent() ? e->Parent()->ToElement() : nullptr) {
    const bool is_root = !e->Parent() || !e->Parent()->ToElement();
    const std::string tag = e->Name();
    if (is_root && (tag == "robot" || tag == "sdf")) break;  // says nothing the source does not
    path = describe(e) + (path.empty() ? "" : "/") + path;
  }
  return path;
}

Eigen::Isometry3d fromXyzRpy(const std::vector<double>& v) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  t.linear() = (Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return t;
}

}  // namespace

NumberCheck positive() {
  return {[](double v) { return v > 0; }, "> 0"};
}
NumberCheck nonNegative() {
  return {[](double v) { return v >= 0; }, ">= 0"};
}
NumberCheck greaterThan(double bound, const std::string& what) {
  return {[bound](double v) { return v > bound; }, "> " + what + " (" + formatNumber(bound) + ")"};
}
NumberCheck atLeast(double bound, const std::string& what) {
  return {[bound](double v) { return v >= bound; }, ">= " + what + " (" + formatNumber(bound) + ")"};
}

std::string formatNumber(double v) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << v;
  return out.str();
}

std::string pluginLibraryName(const std::string& filename) {
  return trim(filename).substr(trim(filename).find_last_of('/') + 1);  // npos + 1 == 0
}

SdfElement::SdfElement(std::shared_ptr<const tinyxml2::XMLDocument> doc, const tinyxml2::XMLElement* element,
                       const tinyxml2::XMLElement* parent, std::string missing_tag, std::string source)
    : doc_(std::move(doc)),
      element_(element),
      parent_(parent),
      missing_tag_(std::move(missing_tag)),
      source_(std::move(source)) {}

SdfElement SdfElement::parse(const std::string& xml, const std::string& source) {
  auto doc = std::make_shared<tinyxml2::XMLDocument>();
  if (doc->Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw DescriptionError(source + ": malformed XML at line " + std::to_string(doc->ErrorLineNum()) + ": " +
                           doc->ErrorStr());
  const XMLElement* root = doc->RootElement();
  if (!root) throw DescriptionError(source + ": no XML element found");
  return SdfElement(doc, root, nullptr, "", source);
}

std::string SdfElement::tag() const { return element_ ? element_->Name() : missing_tag_; }

std::string SdfElement::path() const {
  if (element_) return pathTo(element_);
  if (!parent_) return "<" + missing_tag_ + ">";
  const std::string above = pathTo(parent_);
  return (above.empty() ? "" : above + "/") + "<" + missing_tag_ + ">";
}

std::string SdfElement::attribute(const char* name, const std::string& fallback) const {
  const char* v = element_ ? element_->Attribute(name) : nullptr;
  return v ? v : fallback;
}

bool SdfElement::hasAttribute(const char* name) const { return element_ && element_->Attribute(name); }

std::string SdfElement::text() const { return element_ && element_->GetText() ? trim(element_->GetText()) : ""; }

SdfElement SdfElement::child(const char* tag) const {
  const XMLElement* c = element_ ? element_->FirstChildElement(tag) : nullptr;
  // An absent child of an absent element still knows the nearest element above it.
  const XMLElement* parent = element_ ? element_ : parent_;
  const std::string missing = element_ ? tag : missing_tag_ + ">/<" + tag;
  return c ? SdfElement(doc_, c, nullptr, "", source_) : SdfElement(doc_, nullptr, parent, missing, source_);
}

SdfElement SdfElement::requiredChild(const char* tag) const {
  SdfElement c = child(tag);
  if (!c) fail(std::string("missing required element <") + tag + ">");
  return c;
}

std::vector<SdfElement> SdfElement::children(const char* tag) const {
  std::vector<SdfElement> out;
  if (!element_) return out;
  for (const XMLElement* c = element_->FirstChildElement(tag); c; c = c->NextSiblingElement(tag))
    out.push_back(SdfElement(doc_, c, nullptr, "", source_));
  return out;
}

SdfElement SdfElement::parent() const {
  if (!element_) return parent_ ? SdfElement(doc_, parent_, nullptr, "", source_) : SdfElement();
  const XMLElement* p = element_->Parent() ? element_->Parent()->ToElement() : nullptr;
  return p ? SdfElement(doc_, p, nullptr, "", source_) : SdfElement();
}

std::string SdfElement::xml() const {
  if (!element_) return "";
  tinyxml2::XMLPrinter printer;
  element_->Accept(&printer);
  return printer.CStr();
}

void SdfElement::fail(const std::string& what) const {
  const std::string where = path();
  throw DescriptionError(source_ + ": " + (where.empty() ? "" : where + ": ") + what);
}

void SdfElement::expected(const std::string& form) const { fail("expected " + form + ", got '" + text() + "'"); }

double SdfElement::asNumber(const NumberCheck& check) const {
  const std::string form = check.expectation.empty() ? "a number" : "a number " + check.expectation;
  double v = 0;
  if (!toDouble(text(), v) || (check.ok && !check.ok(v))) expected(form);
  return v;
}

std::vector<double> SdfElement::asNumbers(size_t min_count, size_t max_count) const {
  std::vector<double> out;
  bool ok = true;
  std::istringstream words(text());
  for (std::string word; ok && words >> word;) {
    double v = 0;
    ok = toDouble(word, v);
    out.push_back(v);
  }
  if (!ok || out.size() < min_count || out.size() > max_count) {
    expected(std::to_string(min_count) + (max_count != min_count ? " to " + std::to_string(max_count) : "") +
             (max_count == 1 ? " number" : " numbers"));
  }
  return out;
}

long SdfElement::asInteger(long min, long max) const {
  const std::string t = text();
  long v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || v < min || v > max)
    expected("an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return v;
}

bool SdfElement::asBoolean() const {
  const std::string t = lower(text());
  if (t == "true" || t == "1") return true;
  if (t == "false" || t == "0") return false;
  expected("true, false, 1 or 0");
}

Eigen::Vector3d SdfElement::asVector3() const {
  const std::vector<double> v = asNumbers(3, 3);
  return {v[0], v[1], v[2]};
}

Eigen::Isometry3d SdfElement::asPose() const {
  for (const char* attribute : {"relative_to", "frame"}) {
    const std::string frame = this->attribute(attribute);
    if (!frame.empty())
      fail(std::string(attribute) + "='" + frame + "' is not supported; poses are relative to the parent element");
  }
  std::vector<double> v;
  try {
    v = asNumbers(6, 6);
  } catch (const DescriptionError&) {
    expected("6 numbers 'x y z roll pitch yaw'");
  }
  if (lower(attribute("degrees")) == "true" || attribute("degrees") == "1")
    for (int i = 3; i < 6; ++i) v[i] *= EIGEN_PI / 180.0;
  return fromXyzRpy(v);
}

double SdfElement::number(const char* tag, double fallback, const NumberCheck& check) const {
  const SdfElement c = child(tag);
  if (c) return c.asNumber(check);
  if (check.ok && !check.ok(fallback))
    c.fail("expected a number " + check.expectation + ", got nothing (the default is " + formatNumber(fallback) + ")");
  return fallback;
}

long SdfElement::integer(const char* tag, long fallback, long min, long max) const {
  const SdfElement c = child(tag);
  return c ? c.asInteger(min, max) : fallback;
}

bool SdfElement::boolean(const char* tag, bool fallback) const {
  const SdfElement c = child(tag);
  return c ? c.asBoolean() : fallback;
}

std::string SdfElement::string(const char* tag, const std::string& fallback) const {
  const SdfElement c = child(tag);
  return c ? c.text() : fallback;
}

std::string SdfElement::name(const char* tag, const std::string& fallback) const {
  const SdfElement c = child(tag);
  if (!c) return fallback;
  if (c.text().empty()) c.expected("a name");
  return c.text();
}

Eigen::Vector3d SdfElement::vector3(const char* tag, const Eigen::Vector3d& fallback) const {
  const SdfElement c = child(tag);
  return c ? c.asVector3() : fallback;
}

Eigen::Isometry3d SdfElement::pose(const char* tag) const {
  const SdfElement c = child(tag);
  return c ? c.asPose() : Eigen::Isometry3d::Identity();
}

}  // namespace bullet_sim
