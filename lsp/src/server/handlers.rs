//! The requests: each runs an `ide` function on a snapshot off the main
//! loop (see [`Backend::on_snapshot`]) and converts the answer.

use std::sync::Arc;

use rapid_analyzer::ide;
use tower_lsp_server::LanguageServer;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::request::{
    GotoDeclarationParams, GotoDeclarationResponse, GotoTypeDefinitionParams,
    GotoTypeDefinitionResponse,
};
use tower_lsp_server::ls_types::*;

use super::diagnostics;
use super::requests;
use super::state::path_of;

use super::backend::*;
use super::publish::convert_diagnostics;

impl LanguageServer for Backend {
    async fn did_save(&self, _: DidSaveTextDocumentParams) {}

    async fn shutdown(&self) -> Result<()> {
        self.handle_shutdown().await
    }

    async fn initialize(&self, params: InitializeParams) -> Result<InitializeResult> {
        self.handle_initialize(params).await
    }
    async fn initialized(&self, params: InitializedParams) {
        self.handle_initialized(params).await
    }

    async fn did_open(&self, params: DidOpenTextDocumentParams) {
        self.handle_did_open(params).await
    }
    async fn did_change(&self, params: DidChangeTextDocumentParams) {
        self.handle_did_change(params).await
    }
    async fn did_close(&self, params: DidCloseTextDocumentParams) {
        self.handle_did_close(params).await
    }
    async fn did_change_watched_files(&self, params: DidChangeWatchedFilesParams) {
        self.handle_did_change_watched_files(params).await
    }
    async fn did_change_workspace_folders(&self, params: DidChangeWorkspaceFoldersParams) {
        self.handle_did_change_workspace_folders(params).await
    }
    async fn did_change_configuration(&self, params: DidChangeConfigurationParams) {
        self.handle_did_change_configuration(params).await
    }

    async fn diagnostic(
        &self,
        params: DocumentDiagnosticParams,
    ) -> Result<DocumentDiagnosticReportResult> {
        let previous = params.previous_result_id;
        let computed = self
            .on_checked(&params.text_document.uri, "diagnostics", |snap, raw| {
                convert_diagnostics(snap, raw)
            })
            .await?;
        let items = computed.unwrap_or_default();
        let result_id = diagnostics::result_id(&items);
        let report = if previous.as_deref() == Some(result_id.as_str()) {
            DocumentDiagnosticReport::Unchanged(RelatedUnchangedDocumentDiagnosticReport {
                related_documents: None,
                unchanged_document_diagnostic_report: UnchangedDocumentDiagnosticReport {
                    result_id,
                },
            })
        } else {
            DocumentDiagnosticReport::Full(RelatedFullDocumentDiagnosticReport {
                related_documents: None,
                full_document_diagnostic_report: FullDocumentDiagnosticReport {
                    result_id: Some(result_id),
                    items,
                },
            })
        };
        Ok(DocumentDiagnosticReportResult::Report(report))
    }

    async fn workspace_diagnostic(
        &self,
        params: WorkspaceDiagnosticParams,
    ) -> Result<WorkspaceDiagnosticReportResult> {
        Ok(self.workspace_report(params).await)
    }

    async fn hover(&self, params: HoverParams) -> Result<Option<Hover>> {
        let p = params.text_document_position_params;
        let pos = p.position;
        Ok(self
            .on_snapshot(&p.text_document.uri, "hover", move |s| {
                requests::hover(s, pos)
            })
            .await?
            .flatten())
    }

    async fn completion(&self, params: CompletionParams) -> Result<Option<CompletionResponse>> {
        let trigger = params
            .context
            .filter(|c| c.trigger_kind == CompletionTriggerKind::TRIGGER_CHARACTER)
            .and_then(|c| c.trigger_character)
            .and_then(|c| c.chars().next());
        let p = params.text_document_position;
        let pos = p.position;
        let uri = p.text_document.uri;
        let lazy = self
            .mutate("completion", |s| {
                s.last_completion = Some((uri.clone(), pos));
                s.caps.resolve_completion_detail
            })
            .unwrap_or(false);
        Ok(self
            .on_snapshot(&uri, "completion", move |s| {
                requests::completion(s, pos, lazy, trigger)
            })
            .await?
            .map(CompletionResponse::List))
    }

    async fn completion_resolve(&self, item: CompletionItem) -> Result<CompletionItem> {
        // An item sent without its detail finds it again in the list it
        // came from.
        let origin = self
            .mutate("completion resolve", |s| {
                let (uri, pos) = s.last_completion.clone()?;
                Some((s.snapshot(&uri)?, pos))
            })
            .flatten();
        self.blocking("completion resolve", move || {
            requests::resolve_completion(item, origin.as_ref().map(|(s, p)| (s, *p)))
        })
        .await
    }

    async fn signature_help(&self, params: SignatureHelpParams) -> Result<Option<SignatureHelp>> {
        let p = params.text_document_position_params;
        let pos = p.position;
        Ok(self
            .on_snapshot(&p.text_document.uri, "signature help", move |s| {
                requests::signature_help(s, pos)
            })
            .await?
            .flatten())
    }

    async fn goto_definition(
        &self,
        params: GotoDefinitionParams,
    ) -> Result<Option<GotoDefinitionResponse>> {
        self.goto(
            params.text_document_position_params,
            "definition",
            ide::definition,
        )
        .await
    }

    async fn goto_declaration(
        &self,
        params: GotoDeclarationParams,
    ) -> Result<Option<GotoDeclarationResponse>> {
        self.goto(
            params.text_document_position_params,
            "declaration",
            ide::definition,
        )
        .await
    }

    async fn goto_type_definition(
        &self,
        params: GotoTypeDefinitionParams,
    ) -> Result<Option<GotoTypeDefinitionResponse>> {
        self.goto(
            params.text_document_position_params,
            "type definition",
            ide::type_definition,
        )
        .await
    }

    async fn references(&self, params: ReferenceParams) -> Result<Option<Vec<Location>>> {
        let p = params.text_document_position;
        let pos = p.position;
        let decl = params.context.include_declaration;
        self.on_snapshot_with_peers(&p.text_document.uri, pos, "references", move |s| {
            let found = ide::references(&s.task, s.unit_idx, s.map().offset(pos), decl, &s.peers);
            requests::locations(s, found)
        })
        .await
    }

    async fn document_highlight(
        &self,
        params: DocumentHighlightParams,
    ) -> Result<Option<Vec<DocumentHighlight>>> {
        let p = params.text_document_position_params;
        let pos = p.position;
        self.on_snapshot(&p.text_document.uri, "document highlight", move |s| {
            requests::document_highlights(s, pos)
        })
        .await
    }

    async fn prepare_rename(
        &self,
        params: TextDocumentPositionParams,
    ) -> Result<Option<PrepareRenameResponse>> {
        let pos = params.position;
        let answer = self
            .on_snapshot(&params.text_document.uri, "prepare rename", move |s| {
                ide::prepare_rename(&s.task, s.unit_idx, s.map().offset(pos))
                    .map(|r| PrepareRenameResponse::Range(s.map().range(r)))
            })
            .await?;
        match answer {
            None => Ok(None),
            Some(Ok(r)) => Ok(Some(r)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }

    async fn rename(&self, params: RenameParams) -> Result<Option<WorkspaceEdit>> {
        let p = params.text_document_position;
        let pos = p.position;
        let new_name = params.new_name;
        let answer = self
            .on_snapshot_with_peers(&p.text_document.uri, pos, "rename", move |s| {
                ide::rename(
                    &s.task,
                    s.unit_idx,
                    s.map().offset(pos),
                    &new_name,
                    &s.peers,
                )
                .map(|files| requests::workspace_edit(s, files))
            })
            .await?;
        match answer {
            None => Ok(None),
            Some(Ok(edit)) => Ok(Some(edit)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }

    async fn document_symbol(
        &self,
        params: DocumentSymbolParams,
    ) -> Result<Option<DocumentSymbolResponse>> {
        Ok(self
            .on_snapshot(&params.text_document.uri, "document symbols", |s| {
                requests::document_symbols(s)
            })
            .await?
            .map(DocumentSymbolResponse::Nested))
    }

    async fn symbol(
        &self,
        params: WorkspaceSymbolParams,
    ) -> Result<Option<WorkspaceSymbolResponse>> {
        let (tasks, encoding, uris) = self
            .mutate("workspace symbols", |s| {
                (s.ws.tasks(), s.encoding, s.open_uris())
            })
            .ok_or_else(|| internal_error("workspace symbols"))?;
        let query = params.query;
        let found = self
            .blocking("workspace symbols", move || {
                requests::workspace_symbols(&tasks, &query, encoding, &uris)
            })
            .await?;
        Ok(Some(WorkspaceSymbolResponse::Nested(found)))
    }

    async fn semantic_tokens_full(
        &self,
        params: SemanticTokensParams,
    ) -> Result<Option<SemanticTokensResult>> {
        let uri = params.text_document.uri;
        let Some(data) = self
            .on_snapshot(&uri, "semantic tokens", |s| {
                requests::semantic_tokens(s, None)
            })
            .await?
        else {
            return Ok(None);
        };
        let result_id = self.remember_tokens(&uri, &data);
        Ok(Some(SemanticTokensResult::Tokens(SemanticTokens {
            result_id: Some(result_id),
            data,
        })))
    }

    async fn semantic_tokens_full_delta(
        &self,
        params: SemanticTokensDeltaParams,
    ) -> Result<Option<SemanticTokensFullDeltaResult>> {
        let uri = params.text_document.uri;
        let previous = self
            .shared
            .lock()
            .semantic
            .get(&path_of(&uri))
            .filter(|(id, _)| *id == params.previous_result_id)
            .map(|(_, data)| data.clone());
        let Some(data) = self
            .on_snapshot(&uri, "semantic tokens", |s| {
                requests::semantic_tokens(s, None)
            })
            .await?
        else {
            return Ok(None);
        };
        let flat = requests::tokens_to_flat(&data);
        let result_id = self.remember_tokens(&uri, &data);
        Ok(Some(match previous {
            Some(old) => SemanticTokensFullDeltaResult::TokensDelta(SemanticTokensDelta {
                result_id: Some(result_id),
                edits: requests::semantic_delta(&old, &flat).into_iter().collect(),
            }),
            None => SemanticTokensFullDeltaResult::Tokens(SemanticTokens {
                result_id: Some(result_id),
                data,
            }),
        }))
    }

    async fn semantic_tokens_range(
        &self,
        params: SemanticTokensRangeParams,
    ) -> Result<Option<SemanticTokensRangeResult>> {
        let range = params.range;
        Ok(self
            .on_snapshot(&params.text_document.uri, "semantic tokens", move |s| {
                let span = s.map().offset_range(range);
                requests::semantic_tokens(s, Some(span))
            })
            .await?
            .map(|data| {
                SemanticTokensRangeResult::Tokens(SemanticTokens {
                    result_id: None,
                    data,
                })
            }))
    }

    async fn folding_range(&self, params: FoldingRangeParams) -> Result<Option<Vec<FoldingRange>>> {
        self.on_snapshot(&params.text_document.uri, "folding ranges", |s| {
            requests::folding_ranges(s)
        })
        .await
    }

    async fn selection_range(
        &self,
        params: SelectionRangeParams,
    ) -> Result<Option<Vec<SelectionRange>>> {
        let positions = params.positions;
        self.on_snapshot(&params.text_document.uri, "selection ranges", move |s| {
            requests::selection_ranges(s, &positions)
        })
        .await
    }

    async fn inlay_hint(&self, params: InlayHintParams) -> Result<Option<Vec<InlayHint>>> {
        let range = params.range;
        self.on_snapshot(&params.text_document.uri, "inlay hints", move |s| {
            requests::inlay_hints(s, range)
        })
        .await
    }

    async fn code_action(&self, params: CodeActionParams) -> Result<Option<CodeActionResponse>> {
        let range = params.range;
        self.on_snapshot(&params.text_document.uri, "code actions", move |s| {
            requests::code_actions(s, range)
        })
        .await
    }

    async fn formatting(&self, params: DocumentFormattingParams) -> Result<Option<Vec<TextEdit>>> {
        let uri = params.text_document.uri;
        let options = self.format_options();
        match self
            .on_snapshot(&uri, "formatting", move |s| {
                requests::format(s, None, &options)
            })
            .await?
        {
            None => Ok(None),
            Some(Ok(edits)) => Ok(Some(edits)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }

    async fn range_formatting(
        &self,
        params: DocumentRangeFormattingParams,
    ) -> Result<Option<Vec<TextEdit>>> {
        let uri = params.text_document.uri;
        let range = params.range;
        let options = self.format_options();
        match self
            .on_snapshot(&uri, "formatting", move |s| {
                requests::format(s, Some(range), &options)
            })
            .await?
        {
            None => Ok(None),
            Some(Ok(edits)) => Ok(Some(edits)),
            Some(Err(why)) => Err(request_failed(why)),
        }
    }
}

/// The parameters of `rapid/indentation`.
#[derive(Debug, serde::Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IndentationParams {
    pub text_document: TextDocumentIdentifier,
}

/// The answer of `rapid/indentation`: columns per level, and tabs or
/// spaces.
#[derive(Debug, serde::Serialize)]
pub struct IndentationResult {
    pub width: usize,
    pub tabs: bool,
}

impl Backend {
    /// `rapid/indentation`: how `rapid fmt` (and formatting here) indents
    /// the document, with the `[format]` settings: an editor sets its own
    /// indentation from it (Neovim's `shiftwidth` and `expandtab`), so that
    /// the lines it indents are indented as the formatter would.
    pub async fn indentation(
        &self,
        params: IndentationParams,
    ) -> Result<Option<IndentationResult>> {
        let options = self.format_options();
        self.on_snapshot(&params.text_document.uri, "indentation", move |s| {
            let found = rapid_analyzer::format::indentation(&s.unit.text, &options);
            IndentationResult {
                width: found.width,
                tabs: found.tabs,
            }
        })
        .await
    }

    /// Keeps the tokens sent for a document, for the next delta request.
    pub(super) fn remember_tokens(&self, uri: &Uri, data: &[SemanticToken]) -> String {
        let flat = Arc::new(requests::tokens_to_flat(data));
        self.mutate("semantic tokens", |s| {
            let id = s.next_id().to_string();
            s.semantic.insert(path_of(uri), (id.clone(), flat));
            id
        })
        .unwrap_or_default()
    }
}

#[cfg(test)]
use serde_json::Value;

#[cfg(test)]
impl Backend {
    pub async fn test_panic(&self) -> Result<Value> {
        self.blocking("the test method", || -> Value {
            panic!("deliberate test panic")
        })
        .await
    }
}
