#include "window/pigment_fit_panel.hpp"

#include <impasto/data/colorimetry.hpp>
#include <impasto/data/lights.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "window/plot.hpp"

namespace impasto::app::window {

void PigmentFitPanel::fit(const std::string& path) {
  std::snprintf(path_, sizeof path_, "%s", path.c_str());
  error_.clear();
  samples_.clear();
  problem_.reset();
  result_.reset();
  try {
    problem_ = data::read_ks_measurements(path);
    result_ = data::fit_kubelka_munk(*problem_);
    const data::Spectrum d65 = data::light_from_spec("D65");
    std::vector<const data::Pigment*> fitted;
    for (const auto& p : result_->pigments) fitted.push_back(&p);
    const std::string from = std::filesystem::path(path).filename().string();
    for (auto& p : result_->pigments) {
      p.metadata["fitted_from"] = from;
      p.metadata["units"] = "K and S relative to the S of " + problem_->reference_pigment;
    }
    for (std::size_t i = 0; i < problem_->samples.size(); ++i) {
      const data::KsSample& sample = problem_->samples[i];
      Sample row;
      row.name = sample.name;
      row.measured = sample.reflectance;
      row.fitted = data::mixture_reflectance(fitted, sample.concentrations, problem_->saunderson);
      row.delta_e = data::reflectance_delta_e(row.measured, row.fitted, d65);
      row.rms = result_->residuals[i].rms_reflectance;
      row.max_abs = result_->residuals[i].max_reflectance;
      samples_.push_back(std::move(row));
    }
    chosen_ = 0;
  } catch (const std::exception& e) {
    error_ = e.what();
    problem_.reset();
    result_.reset();
  }
}

double PigmentFitPanel::max_delta_e() const {
  double worst = samples_.empty() ? std::nan("") : 0.0;
  for (const Sample& s : samples_) worst = std::max(worst, s.delta_e);
  return worst;
}

void PigmentFitPanel::draw(
    const std::function<void(const std::vector<data::Pigment>&, bool)>& save) {
  ImGui::TextWrapped(
      "A measurement set: reflectances of masstones, tints and mixtures with their "
      "concentrations (docs/pigments.md, '# mix NAME: A=0.5; B=0.5').");
  ImGui::SetNextItemWidth(420);
  ImGui::InputText("measurements CSV", path_, sizeof path_);
  ImGui::SameLine();
  if (ImGui::Button("Fit")) fit(path_);
  if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error_.c_str());
  if (!result_) return;

  ImGui::Text("%zu pigments, %zu samples; reference %s", result_->pigments.size(), samples_.size(),
              problem_->reference_pigment.c_str());
  if (ImGui::BeginTable("##fit", 4,
                        ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY,
                        ImVec2(0, 150))) {
    ImGui::TableSetupColumn("sample");
    ImGui::TableSetupColumn("dE00 (D65)");
    ImGui::TableSetupColumn("rms R");
    ImGui::TableSetupColumn("max |dR|");
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const Sample& s = samples_[i];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (ImGui::Selectable(s.name.c_str(), chosen_ == static_cast<int>(i),
                            ImGuiSelectableFlags_SpanAllColumns))
        chosen_ = static_cast<int>(i);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", s.delta_e);
      ImGui::TableNextColumn();
      ImGui::Text("%.2e", s.rms);
      ImGui::TableNextColumn();
      ImGui::Text("%.2e", s.max_abs);
    }
    ImGui::EndTable();
  }
  if (chosen_ < static_cast<int>(samples_.size())) {
    const Sample& s = samples_[static_cast<std::size_t>(chosen_)];
    const PlotSeries curves[] = {
        {"measured", s.measured.wavelengths_nm, s.measured.values, IM_COL32(240, 240, 240, 255)},
        {"fitted", s.fitted.wavelengths_nm, s.fitted.values, IM_COL32(255, 140, 60, 255), true}};
    PlotOptions o;
    o.id = "##fit_plot";
    o.title = "reflectance of " + s.name;
    o.size = ImVec2(ImGui::GetContentRegionAvail().x, 170);
    draw_plot(o, curves);
  }
  ImGui::Checkbox("replace my pigments of the same name (metadata kept)", &overwrite_);
  if (ImGui::Button("Save to my library")) save(result_->pigments, overwrite_);
}

}  // namespace impasto::app::window
