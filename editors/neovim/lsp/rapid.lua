-- Configuration of the rapid language server for Neovim 0.11's vim.lsp.config
-- (found on 'runtimepath' as lsp/rapid.lua); enable it with vim.lsp.enable('rapid').
return {
  cmd = { 'rapid', 'lsp' },
  filetypes = { 'rapid' },
  root_markers = { 'rapid.toml', 'EIO.cfg', 'eio.cfg', '.git' },
  settings = {},
}
