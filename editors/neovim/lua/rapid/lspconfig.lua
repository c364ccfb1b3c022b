-- The rapid language server as an nvim-lspconfig server configuration, for
-- users of that plugin (with Neovim 0.10, or older lspconfig setups):
--
--   require('rapid.lspconfig').register()
--   require('lspconfig').rapid.setup({})
local M = {}

M.default_config = {
  cmd = { 'rapid', 'lsp' },
  filetypes = { 'rapid' },
  single_file_support = true,
  settings = {},
}

--- The project root of a file (see require('rapid').find_root); outside
--- any project, the file's folder.
function M.root_dir(fname)
  return require('rapid').find_root(fname) or vim.fs.dirname(fname)
end

--- Adds `rapid` to lspconfig's server configurations (no-op when present).
function M.register()
  local configs = require('lspconfig.configs')
  if configs.rapid == nil then
    configs.rapid = {
      default_config = vim.tbl_extend('force', M.default_config, { root_dir = M.root_dir }),
      docs = {
        description = 'ABB RAPID language server: `rapid lsp` from the rapid tools (cargo install --path lsp).',
      },
    }
  end
end

return M
