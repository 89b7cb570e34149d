// The field outputs of a resumed run: those its checkpoint lists, brought
// into the output folder of the run.
#ifndef vpcontact_resumed_field_outputs_h
#define vpcontact_resumed_field_outputs_h

#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  /// (time, .pvtu file) of field outputs: the content of a .pvd record.
  using FieldOutputRecord = std::vector<std::pair<double, std::string>>;

  /**
   * The field outputs of @p outputs (the .pvd record of a checkpoint) that
   * are complete in the folder @p to, and a note for the screen saying what
   * was brought or left out ("" if nothing). @p from is the folder of the
   * run that wrote them; if it is another folder than @p to, the .pvtu
   * records and the .vtu pieces they name are brought into @p to: as hard
   * links where the file system allows (no disk space; safe, since this
   * program replaces its files by a rename and never changes one in
   * place), else as copies. An output with a file missing in @p from (or
   * in @p to, if @p from is @p to or empty) is left out. Serial; throws if
   * a file cannot be brought.
   */
  std::pair<FieldOutputRecord, std::string>
  bring_field_outputs(const FieldOutputRecord &outputs,
                      const std::string       &from,
                      const std::string       &to);
} // namespace VPContact

#endif
