"""The language server: LSP messages in, the language model's answers out (pygls 2).

Each handler converts between LSP's positions (UTF-16 by default) and the model's
0-based string columns and calls one feature module; no language knowledge lives here.
"""
from __future__ import annotations

import asyncio
import os
from dataclasses import dataclass
from pathlib import Path
from collections.abc import Callable, Iterable, Sequence
from typing import Any

from cattrs import ClassValidationError, transform_error
from lsprotocol import types as t
from pygls.exceptions import JsonRpcException
from pygls.lsp.server import LanguageServer
from pygls.protocol import LanguageServerProtocol, default_converter
from pygls.uris import from_fs_path, to_fs_path
from pygls.workspace.position_codec import PositionCodec, ServerTextPosition, ServerTextRange

from edingcnc_lang import __version__
from edingcnc_lang.syntax.input_limits import MAX_LSP_DOCUMENT_CHARS, MAX_TAB_SIZE
from edingcnc_lang.gcpause import whole_trees
from edingcnc_lang.codes import Severity
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.lint.driver import LintOptions, UnknownCode, is_macro_name, parse_codes
from edingcnc_lang.lsp import actions, completion, formatting, hover, navigation, rename
from edingcnc_lang.lsp import variables
from edingcnc_lang.lsp.lexer import token_at
from edingcnc_lang.lsp.model import LanguageModel, Place, file_name

DEBOUNCE_SECONDS = 0.3  # lint once typing pauses, not on every keystroke
REQUEST_FAILED = -32803  # LSP's RequestFailed: a rename refused, with the reason for the user
CONTENT_MODIFIED = -32801  # LSP's ContentModified: the answer is out of date, the client asks again
SOURCE = "ecnc"
_CONVERTER = default_converter()  # the one pygls answers with, for results turned into JSON in a worker
_KINDS = {"code": t.CompletionItemKind.Keyword, "sub": t.CompletionItemKind.Function,
          "variable": t.CompletionItemKind.Variable, "keyword": t.CompletionItemKind.Keyword,
          "command": t.CompletionItemKind.Method, "function": t.CompletionItemKind.Function}


# LSP positions are unsigned 32-bit numbers; a request outside that range failed to deserialize in
# pygls and was never answered, so the client waited for ever.  Clamped, it gets an answer.
_LARGEST_POSITION = 2**31 - 1


def _clamped_positions(data: Any) -> Any:
    """``data`` with every ``line``/``character`` number inside 0 .. 2**31 - 1."""
    if isinstance(data, dict):
        return {key: (min(max(value, 0), _LARGEST_POSITION)
                      if key in ("line", "character") and isinstance(value, int) and not isinstance(value, bool)
                      else _clamped_positions(value)) for key, value in data.items()}
    if isinstance(data, list):
        return [_clamped_positions(item) for item in data]
    return data


@dataclass(frozen=True)
class _Refused:
    """A request whose params do not fit its method: pygls would drop it unanswered (the client
    waited for ever, as for ``formatting`` with ``tabSize`` -5); it is answered InvalidParams."""

    id: int | str
    method: str
    why: str
    code: int = t.ErrorCodes.InvalidParams


class EcncProtocol(LanguageServerProtocol):
    """pygls's protocol, with out-of-range positions clamped before a request is read and every
    request answered, with an error when its params cannot be read."""

    def structure_message(self, data: dict[str, Any]) -> Any:
        try:
            if isinstance(data, dict) and "params" in data:
                data = {**data, "params": _clamped_positions(data["params"])}
            return super().structure_message(data)
        except (JsonRpcException, RecursionError) as err:
            ident = data.get("id")
            if "jsonrpc" in data and "method" in data and isinstance(ident, (int, str)) and not isinstance(ident, bool):
                method = str(data["method"])[:100]
                if self.get_message_type(method) is None:  # and its params could not be read as JSON-RPC's
                    return _Refused(ident, method, "not a method of ecnc lsp", t.ErrorCodes.MethodNotFound)
                return _Refused(ident, method, "invalid params: " + _reason(err))
            raise

    def handle_message(self, message: Any) -> None:
        if isinstance(message, _Refused):
            self._send_response(message.id, None, t.ResponseError(code=message.code,
                                                                  message=f"{message.method}: {message.why}"))
            return
        super().handle_message(message)


def _reason(err: Exception) -> str:
    """What cattrs found wrong (``invalid value @ $.params.options``), or the exception's message."""
    if isinstance(err, RecursionError):
        return "nested too deeply"
    cause = err.__cause__
    if isinstance(cause, ClassValidationError):
        return "; ".join(transform_error(cause))[:500]
    return str(err)[:500]


class EcncServer(LanguageServer):
    """A pygls server holding one language model and the pending (debounced) lint runs."""

    def __init__(self) -> None:
        super().__init__("ecnc", __version__, text_document_sync_kind=t.TextDocumentSyncKind.Incremental,
                         protocol_cls=EcncProtocol)
        self.too_large: dict[str, int] = {}  # documents past MAX_LSP_DOCUMENT_CHARS: path -> their length
        self.model = LanguageModel()
        self.pending: dict[str, asyncio.TimerHandle] = {}
        self.shut_down = False  # the client asked for a shutdown before exit (exit code 0)
        self.uris: dict[str, str] = {}  # the URI of each open document by path (also "untitled:" ones)

    # ----------------------------------------------------------------- helpers
    def path(self, uri: str) -> str:
        return (to_fs_path(uri) if uri.startswith("file:") else None) or uri

    def uri(self, path: str) -> str:
        return self.uris.get(path) or from_fs_path(path) or path

    def set_text(self, path: str, text: str) -> None:
        """The editor's text of ``path``; past MAX_LSP_DOCUMENT_CHARS an empty one (every request is
        answered at once, with nothing) and a diagnostic that says why."""
        if len(text) > MAX_LSP_DOCUMENT_CHARS:
            self.too_large[path] = len(text)
            text = ""
        else:
            self.too_large.pop(path, None)
        self.model.set_text(path, text)

    def codec(self) -> PositionCodec:
        return self.workspace.position_codec

    def lines(self, path: str) -> Sequence[str]:
        file = self.model.source(path)
        return file.lines if file else ()

    def server_position(self, uri: str, position: t.Position) -> tuple[str, int, int]:
        path = self.path(uri)
        lines = self.lines(path)
        if position.line >= len(lines):  # past the end: nothing there (the codec would clamp it)
            return path, position.line, position.character
        found = self.codec().position_from_client_units(lines, position)
        return path, found.line, found.character

    def locations(self, places: Iterable[Place]) -> list[t.Location]:
        """``location`` of many places: each file's URI and lines looked up once, and a line of
        ASCII (nearly every line of a job) in the same units for the client, so no conversion."""
        files: dict[str, tuple[str, Sequence[str]]] = {}
        found = []
        for place in places:
            known = files.get(place.path)
            if known is None:
                known = files[place.path] = (self.uri(place.path), self.lines(place.path))
            uri, lines = known
            if place.line < len(lines) and lines[place.line].isascii():
                found.append(t.Location(uri, t.Range(t.Position(place.line, place.start),
                                                     t.Position(place.line, place.end))))
            else:
                found.append(self.location(place))
        return found

    def location(self, place: Place) -> t.Location:
        server = ServerTextRange(ServerTextPosition(place.line, place.start), ServerTextPosition(place.line, place.end))
        return t.Location(self.uri(place.path),
                          self.codec().range_to_client_units(self.lines(place.path), server))

    def client_range(self, path: str, line: int, start: int, end: int, end_line: int | None = None) -> t.Range:
        last = line if end_line is None else end_line
        server = ServerTextRange(ServerTextPosition(line, start), ServerTextPosition(last, end))
        return self.codec().range_to_client_units(self.lines(path), server)

    # ----------------------------------------------------------------- diagnostics
    def schedule_lint(self, uri: str, delay: float = DEBOUNCE_SECONDS) -> None:
        """Lint ``uri`` once no change has come for ``delay`` seconds."""
        old = self.pending.pop(uri, None)
        if old is not None:
            old.cancel()
        self.pending[uri] = asyncio.get_running_loop().call_later(delay, self.publish, uri)

    def publish(self, uri: str) -> None:
        self.pending.pop(uri, None)
        path = self.path(uri)
        if path in self.too_large:
            message = (f"this document has {self.too_large[path]:,} characters, more than the language server "
                       f"analyses ({MAX_LSP_DOCUMENT_CHARS:,}); run ecnc lint on it")
            found = t.Diagnostic(range=t.Range(start=t.Position(line=0, character=0), end=t.Position(line=0, character=0)),
                                 message=message, severity=t.DiagnosticSeverity.Information, source=SOURCE)
            self.text_document_publish_diagnostics(t.PublishDiagnosticsParams(uri=uri, diagnostics=[found]))
            return
        if path not in self.model.texts:
            return
        lines = self.lines(path)
        diagnostics = [self.diagnostic(path, lines, d) for d in self.model.lint(path)]
        self.text_document_publish_diagnostics(t.PublishDiagnosticsParams(uri=uri, diagnostics=diagnostics))

    def diagnostic(self, path: str, lines: Sequence[str], found: Diagnostic) -> t.Diagnostic:
        line = max(found.line - 1, 0)
        col = max(found.col - 1, 0)
        text = lines[line] if line < len(lines) else ""
        token = token_at(text, col)
        end = token.end if token is not None and token.start <= col < token.end else len(text)
        return t.Diagnostic(
            range=self.client_range(path, line, col, max(end, col)),
            message=found.message, code=found.code, source=SOURCE,
            severity=t.DiagnosticSeverity.Error if found.severity is Severity.ERROR else t.DiagnosticSeverity.Warning)

    def relint_folder(self, path: str) -> None:
        """After a change to a macro file, the open files beside it may resolve differently."""
        if not is_macro_name(Path(path)):
            return
        for other in self.model.texts:
            if other != path and os.path.dirname(other) == os.path.dirname(path):
                self.schedule_lint(self.uri(other))


server = EcncServer()


def _markdown(text: str) -> t.MarkupContent:
    return t.MarkupContent(kind=t.MarkupKind.Markdown, value=text)


@server.feature(t.INITIALIZE)
def _initialize(ls: EcncServer, params: t.InitializeParams) -> None:
    """``initializationOptions``: ``{"select": "E,S208", "ignore": "F601"}`` as ``ecnc lint`` takes them."""
    options = params.initialization_options if isinstance(params.initialization_options, dict) else {}

    def codes(name: str) -> tuple[str, ...]:  # "E,S208" or ["E", "S208"]
        value = options.get(name) or ""
        return parse_codes(",".join(map(str, value)) if isinstance(value, list) else str(value))

    try:
        ls.model.options = LintOptions(select=codes("select"), ignore=codes("ignore"))
    except UnknownCode as err:  # the editor still works, with every code
        ls.window_show_message(t.ShowMessageParams(
            type=t.MessageType.Warning, message=f"ecnc lsp: select/ignore ignored: no code starts with {err}"))


@server.feature(t.INITIALIZED)
def _initialized(ls: EcncServer, _params: t.InitializedParams) -> None:
    ls.model.roots = [to_fs_path(folder.uri) or folder.uri for folder in ls.workspace.folders.values()]


@server.feature(t.SHUTDOWN)
def _shutdown(ls: EcncServer, _params: None) -> None:
    ls.shut_down = True


@server.feature(t.TEXT_DOCUMENT_DID_OPEN)
def _did_open(ls: EcncServer, params: t.DidOpenTextDocumentParams) -> None:
    path = ls.path(params.text_document.uri)
    ls.uris[path] = params.text_document.uri
    ls.set_text(path, params.text_document.text)
    ls.schedule_lint(params.text_document.uri, 0)
    ls.relint_folder(path)


@server.feature(t.TEXT_DOCUMENT_DID_CHANGE)
def _did_change(ls: EcncServer, params: t.DidChangeTextDocumentParams) -> None:
    uri = params.text_document.uri
    path = ls.path(uri)
    ls.set_text(path, ls.workspace.get_text_document(uri).source)
    ls.schedule_lint(uri)
    ls.relint_folder(path)


@server.feature(t.TEXT_DOCUMENT_DID_SAVE)
def _did_save(ls: EcncServer, params: t.DidSaveTextDocumentParams) -> None:
    ls.schedule_lint(params.text_document.uri, 0)


@server.feature(t.TEXT_DOCUMENT_DID_CLOSE)
def _did_close(ls: EcncServer, params: t.DidCloseTextDocumentParams) -> None:
    uri = params.text_document.uri
    ls.model.set_text(ls.path(uri), None)
    ls.too_large.pop(ls.path(uri), None)
    ls.uris.pop(ls.path(uri), None)
    pending = ls.pending.pop(uri, None)
    if pending is not None:
        pending.cancel()
    ls.text_document_publish_diagnostics(t.PublishDiagnosticsParams(uri=uri, diagnostics=[]))


@server.feature(t.TEXT_DOCUMENT_HOVER)
def _hover(ls: EcncServer, params: t.HoverParams) -> t.Hover | None:
    where = ls.server_position(params.text_document.uri, params.position)
    parts = (variables.hover_text(ls.model, *where), hover.hover_text(ls.model, *where))
    text = "\n\n---\n\n".join(filter(None, parts))
    return t.Hover(contents=_markdown(text)) if text else None


@server.feature(t.TEXT_DOCUMENT_DEFINITION)
def _definition(ls: EcncServer, params: t.DefinitionParams) -> t.Location | None:
    where = ls.server_position(params.text_document.uri, params.position)
    place = navigation.definition(ls.model, *where) or variables.definition(ls.model, *where)
    return ls.location(place) if place else None


async def in_worker(ls: EcncServer, work: Callable[[], Any], result_type: type) -> Any:
    """``work()`` in a worker thread, so that the server answers other requests meanwhile (a rename
    of a sub with 260,000 calls takes seconds), with the collector paused as while parsing (it
    would walk the parsed files again and again as the places pile up); its result turned into
    JSON's lists and dicts there too.  ContentModified if a document changed meanwhile."""
    def unstructured() -> Any:
        with whole_trees():
            return _CONVERTER.unstructure(work(), result_type)

    before = dict(ls.model.texts)
    result = await asyncio.to_thread(unstructured)
    if any(ls.model.texts.get(path) is not text for path, text in before.items()):
        raise JsonRpcException("a document changed while this was worked out: ask again", code=CONTENT_MODIFIED)
    return result


@server.feature(t.TEXT_DOCUMENT_REFERENCES)
async def _references(ls: EcncServer, params: t.ReferenceParams) -> Any:  # list[t.Location], as JSON
    path, line, col = ls.server_position(params.text_document.uri, params.position)

    def work() -> list[t.Location]:
        return ls.locations(navigation.references(ls.model, path, line, col, params.context.include_declaration))
    return await in_worker(ls, work, list[t.Location])


@server.feature(t.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
def _document_symbols(ls: EcncServer, params: t.DocumentSymbolParams) -> list[t.DocumentSymbol]:
    path = ls.path(params.text_document.uri)
    return [t.DocumentSymbol(
        name=symbol.name, kind=t.SymbolKind.Function, detail="Sub",
        range=ls.client_range(path, symbol.first_line, 0, symbol.end_col, symbol.last_line),
        selection_range=ls.location(symbol.selection).range)
        for symbol in navigation.document_symbols(ls.model, path)]


@server.feature(t.TEXT_DOCUMENT_FOLDING_RANGE)
def _folding_ranges(ls: EcncServer, params: t.FoldingRangeParams) -> list[t.FoldingRange]:
    return [t.FoldingRange(start_line=first, end_line=last, kind=t.FoldingRangeKind.Region)
            for first, last in navigation.folding_ranges(ls.model, ls.path(params.text_document.uri))]


@server.feature(t.WORKSPACE_DID_CHANGE_WATCHED_FILES)
def _watched_files(ls: EcncServer, params: t.DidChangeWatchedFilesParams) -> None:
    """A macro file changed on disk (not in the editor): the open files beside it are checked again."""
    for change in params.changes:
        ls.relint_folder(ls.path(change.uri))


@server.feature(t.WORKSPACE_SYMBOL)
def _workspace_symbols(ls: EcncServer, params: t.WorkspaceSymbolParams) -> list[t.SymbolInformation]:
    return [t.SymbolInformation(name=name, kind=kind, location=ls.location(place), container_name=file_name(place.path))
            for found, kind in ((navigation.workspace_symbols(ls.model, params.query), t.SymbolKind.Function),
                                (variables.workspace_symbols(ls.model, params.query), t.SymbolKind.Variable))
            for name, place in found]


@server.feature(t.TEXT_DOCUMENT_COMPLETION, t.CompletionOptions(trigger_characters=["#", " "]))
def _completion(ls: EcncServer, params: t.CompletionParams) -> t.CompletionList:
    path, line, col = ls.server_position(params.text_document.uri, params.position)
    items = []
    offered = completion.complete(ls.model, path, line, col) + variables.complete_names(ls.model, path, line, col)
    for rank, item in enumerate(offered):
        items.append(t.CompletionItem(
            label=item.label, kind=_KINDS[item.kind], detail=item.detail, sort_text=f"{rank:05d}",
            documentation=_markdown(item.documentation) if item.documentation else None,
            text_edit=t.TextEdit(range=ls.client_range(path, line, item.start, col),
                                 new_text=item.insert or item.label)))
    return t.CompletionList(is_incomplete=False, items=items)


@server.feature(t.TEXT_DOCUMENT_CODE_ACTION,
                t.CodeActionOptions(code_action_kinds=[t.CodeActionKind.QuickFix, t.CodeActionKind.RefactorRewrite]))
def _code_actions(ls: EcncServer, params: t.CodeActionParams) -> list[t.CodeAction]:
    uri = params.text_document.uri
    path = ls.path(uri)
    lines = ls.lines(path)
    eol = actions.line_end(ls.model.texts.get(path))
    found: list[t.CodeAction] = []
    for diagnostic in params.context.diagnostics:
        if diagnostic.source != SOURCE:
            continue
        start = ls.codec().position_from_client_units(lines, diagnostic.range.start)
        finding = actions.ShownDiagnostic(str(diagnostic.code or ""), start.line, start.character, diagnostic.message)
        for fix in actions.fixes(finding, lines) + variables.annotation_fixes(ls.model, path, lines, 0, 0, finding):
            edits = [t.TextEdit(range=ls.client_range(path, e.line, e.start, e.end),
                                new_text=e.text.replace("\n", eol)) for e in fix.edits]
            found.append(t.CodeAction(title=fix.title, kind=t.CodeActionKind.QuickFix, diagnostics=[diagnostic],
                                      is_preferred=fix.preferred, edit=t.WorkspaceEdit(changes={uri: edits})))
    cursor = params.range.start
    at = ls.codec().position_from_client_units(lines, cursor) if cursor.line < len(lines) else None
    for fix in variables.annotation_fixes(ls.model, path, lines, at.line, at.character) if at else ():
        edits = [t.TextEdit(range=ls.client_range(path, e.line, e.start, e.end), new_text=e.text.replace("\n", eol))
                 for e in fix.edits]
        found.append(t.CodeAction(title=fix.title, kind=t.CodeActionKind.RefactorRewrite,
                                  edit=t.WorkspaceEdit(changes={uri: edits})))
    return found


@server.feature(t.TEXT_DOCUMENT_INLAY_HINT)
def _inlay_hints(ls: EcncServer, params: t.InlayHintParams) -> list[t.InlayHint]:
    """The name beside every ``#n`` that has one (lsp/variables.py)."""
    path = ls.path(params.text_document.uri)
    lines = ls.lines(path)
    hints = variables.inlay_hints(ls.model, path, params.range.start.line, params.range.end.line)
    return [t.InlayHint(position=ls.client_range(path, h.line, h.col, h.col).start, label=h.label,
                        kind=t.InlayHintKind.Parameter, padding_left=True) for h in hints if h.line < len(lines)]


@server.feature(t.TEXT_DOCUMENT_FORMATTING)
def _formatting(ls: EcncServer, params: t.DocumentFormattingParams) -> list[t.TextEdit] | None:
    path = ls.path(params.text_document.uri)
    file = ls.model.source(path)
    if file is None:
        return None
    lines = file.lines
    options = params.options
    with whole_trees():  # a file with syntax errors: the lines without one (formatting.py)
        indent = " " * min(max(options.tab_size, 1), MAX_TAB_SIZE) if options.insert_spaces else "\t"
        formatted = formatting.format_lines(lines, indent,
                                            None if file.parse_errors else (file.body, file.unit), partial=True)
    if formatted is None:
        return None
    return [t.TextEdit(range=ls.client_range(path, number, 0, len(old)), new_text=new)
            for number, (old, new) in enumerate(zip(lines, formatted)) if old != new]


@server.feature(t.TEXT_DOCUMENT_PREPARE_RENAME)
def _prepare_rename(ls: EcncServer, params: t.PrepareRenameParams) -> t.PrepareRenamePlaceholder | None:
    path, line, col = ls.server_position(params.text_document.uri, params.position)
    named = variables.annotation_name_at(ls.model, path, line, col)
    if named is not None:  # the name of a ;@var annotation: rename edits it there
        return t.PrepareRenamePlaceholder(range=ls.location(named).range,
                                          placeholder=ls.lines(path)[named.line][named.start:named.end])
    try:
        target = rename.target_at(ls.model, path, line, col)
    except rename.RenameRefused as err:
        raise JsonRpcException(str(err), code=REQUEST_FAILED) from None
    if target is None:
        return None
    place = target.place
    return t.PrepareRenamePlaceholder(range=ls.location(place).range,
                                      placeholder=ls.lines(path)[place.line][place.start:place.end])


@server.feature(t.TEXT_DOCUMENT_RENAME)
async def _rename(ls: EcncServer, params: t.RenameParams) -> Any:  # t.WorkspaceEdit, as JSON
    path, line, col = ls.server_position(params.text_document.uri, params.position)
    named = variables.annotation_name_at(ls.model, path, line, col)
    if named is not None:  # the name of a ;@var annotation: rename edits it there
        wrong = variables.check_new_name(params.new_name)
        if wrong:
            raise JsonRpcException(wrong, code=REQUEST_FAILED)
        return t.WorkspaceEdit(changes={ls.uri(path): [t.TextEdit(range=ls.location(named).range,
                                                                  new_text=params.new_name)]})
    text = rename.new_text(params.new_name)

    def work() -> t.WorkspaceEdit:
        try:
            found = rename.rename(ls.model, path, line, col, params.new_name)
        except rename.RenameRefused as err:
            raise JsonRpcException(str(err), code=REQUEST_FAILED) from None
        return t.WorkspaceEdit(changes={ls.uri(file): [t.TextEdit(range=place.range, new_text=text)
                                                       for place in ls.locations(places)]
                                        for file, places in found.items()})
    return await in_worker(ls, work, t.WorkspaceEdit)
