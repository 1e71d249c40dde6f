// A solid's product in a STEP file: MANIFOLD_SOLID_BREP -> the representation listing it among its items -> the
// SHAPE_DEFINITION_REPRESENTATION of that representation -> PRODUCT_DEFINITION_SHAPE -> PRODUCT_DEFINITION ->
// its formation -> PRODUCT (name). Where the product's definition names another representation, a
// SHAPE_REPRESENTATION_RELATIONSHIP (without a transformation: those place one product in another) joins the two.
#include "io/step_names.h"

#include <Interface_EntityIterator.hxx>
#include <Interface_Graph.hxx>
#include <Standard_Failure.hxx>
#include <StepBasic_Product.hxx>
#include <StepBasic_ProductDefinition.hxx>
#include <StepBasic_ProductDefinitionFormation.hxx>
#include <StepRepr_CharacterizedDefinition.hxx>
#include <StepRepr_PropertyDefinition.hxx>
#include <StepRepr_Representation.hxx>
#include <StepRepr_RepresentationRelationshipWithTransformation.hxx>
#include <StepRepr_RepresentedDefinition.hxx>
#include <StepRepr_ShapeRepresentationRelationship.hxx>
#include <StepShape_ManifoldSolidBrep.hxx>
#include <StepShape_ShapeDefinitionRepresentation.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

namespace vox::io {
namespace {

// The product a shape definition representation defines; empty when it is not a named product's.
std::string productName(const Handle(StepShape_ShapeDefinitionRepresentation) & sdr) {
  const Handle(StepRepr_PropertyDefinition) property = sdr->Definition().PropertyDefinition();
  if (property.IsNull()) return {};
  const Handle(StepBasic_ProductDefinition) definition = property->Definition().ProductDefinition();
  if (definition.IsNull() || definition->Formation().IsNull()) return {};
  const Handle(StepBasic_Product) product = definition->Formation()->OfProduct();
  if (product.IsNull() || product->Name().IsNull()) return {};
  return product->Name()->ToCString();
}

// The name of the product whose shape `representation` is, directly or through relationships without a transformation
// (at most `depth` of them).
std::string productOf(const Interface_Graph& graph, const Handle(Standard_Transient) & representation, int depth) {
  for (Interface_EntityIterator it = graph.Sharings(representation); it.More(); it.Next()) {
    const auto sdr = Handle(StepShape_ShapeDefinitionRepresentation)::DownCast(it.Value());
    if (sdr.IsNull()) continue;
    if (std::string name = productName(sdr); !name.empty()) return name;
  }
  if (depth <= 0) return {};
  for (Interface_EntityIterator it = graph.Sharings(representation); it.More(); it.Next()) {
    const auto link = Handle(StepRepr_ShapeRepresentationRelationship)::DownCast(it.Value());
    if (link.IsNull() || it.Value()->IsKind(STANDARD_TYPE(StepRepr_RepresentationRelationshipWithTransformation)))
      continue;
    const Handle(Standard_Transient) other =
        link->Rep1() == representation ? Handle(Standard_Transient)(link->Rep2()) : link->Rep1();
    if (other.IsNull()) continue;
    if (std::string name = productOf(graph, other, depth - 1); !name.empty()) return name;
  }
  return {};
}

// The solids the transfer made from the file's solid B-reps, with their products' names.
std::vector<std::pair<TopoDS_Shape, std::string>> namedSolids(const STEPControl_Reader& reader) {
  std::vector<std::pair<TopoDS_Shape, std::string>> out;
  const Handle(XSControl_WorkSession) session = reader.WS();
  if (session.IsNull() || session->Model().IsNull() || session->TransferReader().IsNull()) return out;
  const Handle(Transfer_TransientProcess) process = session->TransferReader()->TransientProcess();
  if (process.IsNull()) return out;
  const Interface_Graph& graph = session->Graph();
  const Handle(Interface_InterfaceModel) model = session->Model();
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Standard_Transient) entity = model->Value(i);
    if (entity.IsNull() || !entity->IsKind(STANDARD_TYPE(StepShape_ManifoldSolidBrep))) continue;
    const TopoDS_Shape solid = TransferBRep::ShapeResult(process, entity);
    if (solid.IsNull()) continue;
    for (Interface_EntityIterator it = graph.Sharings(entity); it.More(); it.Next()) {
      if (it.Value().IsNull()) continue;
      if (std::string name = productOf(graph, it.Value(), 2); !name.empty()) {
        out.emplace_back(solid, std::move(name));
        break;
      }
    }
  }
  return out;
}

}  // namespace

std::vector<std::pair<TopoDS_Shape, std::string>> stepSolidNames(const STEPControl_Reader& reader) {
  try {
    return namedSolids(reader);
  } catch (const Standard_Failure&) {
    return {};  // names are a courtesy: a file whose structure Open CASCADE cannot follow keeps "solid N"
  }
}

}  // namespace vox::io
